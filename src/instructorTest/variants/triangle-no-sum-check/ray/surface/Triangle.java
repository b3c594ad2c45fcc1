package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Known wrong: checks beta ≥ 0 and gamma ≥ 0 but not beta + gamma ≤ 1 (hits a parallelogram). */
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
        Vec3 edge1 = v1.minus(v0);
        Vec3 edge2 = v2.minus(v0);
        Vec3 pvec = ray.direction.cross(edge2);
        double det = edge1.dot(pvec);
        if (det == 0) {
            return false;
        }
        double invDet = 1 / det;
        Vec3 tvec = ray.origin.minus(v0);
        double u = tvec.dot(pvec) * invDet;
        Vec3 qvec = tvec.cross(edge1);
        double v = ray.direction.dot(qvec) * invDet;
        if (u < 0 || v < 0 || u > 1 || v > 1) {
            return false;
        }
        double t = edge2.dot(qvec) * invDet;
        if (!(t > ray.start && t < ray.end)) {
            return false;
        }
        out.t = t;
        out.location = ray.pointAt(t);
        out.normal = normalAt(u, v);
        out.surface = this;
        out.beta = u;
        out.gamma = v;
        out.texU = (1 - u - v) * vt0.x + u * vt1.x + v * vt2.x;
        out.texV = (1 - u - v) * vt0.y + u * vt1.y + v * vt2.y;
        return true;
    }
}
