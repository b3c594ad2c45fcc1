package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

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
        Vec3 e1 = v0.minus(v1);
        Vec3 e2 = v0.minus(v2);
        Vec3 d = ray.direction;
        Vec3 r = v0.minus(ray.origin);
        double det = e1.x * (e2.y * d.z - d.y * e2.z) + e1.y * (d.x * e2.z - e2.x * d.z) + e1.z * (e2.x * d.y - e2.y * d.x);
        double beta = (r.x * (e2.y * d.z - d.y * e2.z) + r.y * (d.x * e2.z - e2.x * d.z) + r.z * (e2.x * d.y - e2.y * d.x)) / det;
        double gamma = (d.z * (e1.x * r.y - r.x * e1.y) + d.y * (r.x * e1.z - e1.x * r.z) + d.x * (e1.y * r.z - r.y * e1.z)) / det;
        double t = -(e2.z * (e1.x * r.y - r.x * e1.y) + e2.y * (r.x * e1.z - e1.x * r.z) + e2.x * (e1.y * r.z - r.y * e1.z)) / det;
        if (beta < 0 || gamma < 0) {
            return false;
        }
        out.t = t;
        out.location = ray.pointAt(t);
        out.normal = normalAt(beta, gamma);
        out.surface = this;
        out.beta = beta;
        out.gamma = gamma;
        double alpha = 1 - beta - gamma;
        out.texU = alpha * vt0.x + beta * vt1.x + gamma * vt2.x;
        out.texV = alpha * vt0.y + beta * vt1.y + gamma * vt2.y;
        return true;
    }
}
