package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Cramer's rule written with vectors: each determinant a triple product A·(B × C). */
public class Triangle extends TriangleSurface {
    public Triangle() {
    }

    public Triangle(Vec3 v0, Vec3 v1, Vec3 v2) {
        super(v0, v1, v2);
    }

    public Triangle(Vec3 v0, Vec3 v1, Vec3 v2, Vec3 n0, Vec3 n1, Vec3 n2) {
        super(v0, v1, v2, n0, n1, n2);
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        // beta·A + gamma·B + t·d = R with A = v0 − v1, B = v0 − v2, R = v0 − p.
        Vec3 a = v0.minus(v1);
        Vec3 b = v0.minus(v2);
        Vec3 d = ray.direction;
        Vec3 r = v0.minus(ray.origin);
        double det = a.dot(b.cross(d));
        if (det == 0) {
            return false;
        }
        double beta = r.dot(b.cross(d)) / det;
        double gamma = a.dot(r.cross(d)) / det;
        double t = a.dot(b.cross(r)) / det;
        boolean inside = beta >= 0 && gamma >= 0 && beta + gamma <= 1;
        if (!inside || !(t > ray.start && t < ray.end)) {
            return false;
        }
        IntersectionRecord hit = new IntersectionRecord();
        hit.t = t;
        hit.location = ray.origin.plus(d.times(t));
        hit.normal = normalAt(beta, gamma);
        hit.surface = this;
        hit.beta = beta;
        hit.gamma = gamma;
        hit.texU = vt0.x + beta * (vt1.x - vt0.x) + gamma * (vt2.x - vt0.x);
        hit.texV = vt0.y + beta * (vt1.y - vt0.y) + gamma * (vt2.y - vt0.y);
        out.set(hit);
        return true;
    }
}
