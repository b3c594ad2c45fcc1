package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** The plane first, then barycentrics as ratios of signed areas (cross products against the normal). */
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
        Vec3 e1 = v1.minus(v0);
        Vec3 e2 = v2.minus(v0);
        Vec3 n = e1.cross(e2);
        double denominator = n.dot(ray.direction);
        if (denominator == 0) {
            return false;
        }
        double t = n.dot(v0.minus(ray.origin)) / denominator;
        if (t <= ray.start || t >= ray.end) {
            return false;
        }
        Vec3 p = ray.pointAt(t);
        double area = n.dot(n);
        // p − v0 = beta·e1 + gamma·e2, so (p − v0) × e2 = beta·n and e1 × (p − v0) = gamma·n.
        double beta = n.dot(p.minus(v0).cross(e2)) / area;
        double gamma = n.dot(e1.cross(p.minus(v0))) / area;
        if (beta < 0 || gamma < 0 || beta + gamma > 1) {
            return false;
        }
        out.t = t;
        out.location = p;
        out.normal = normalAt(beta, gamma);
        out.surface = this;
        out.beta = beta;
        out.gamma = gamma;
        // vt0 + β(vt1 − vt0) + γ(vt2 − vt0): the same blend, written from the first corner.
        Vec3 uv = vt0.plus(vt1.minus(vt0).times(beta)).plus(vt2.minus(vt0).times(gamma));
        out.texU = uv.x;
        out.texV = uv.y;
        return true;
    }
}
