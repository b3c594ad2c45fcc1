package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Known wrong: Cramer's rule without the check of t against ray.start and ray.end, so hits behind the ray's start (and past a shadow ray's light) count. */
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
        double a = v0.x - v1.x, b = v0.y - v1.y, c = v0.z - v1.z;
        double d = v0.x - v2.x, e = v0.y - v2.y, f = v0.z - v2.z;
        double g = ray.direction.x, h = ray.direction.y, i = ray.direction.z;
        double j = v0.x - ray.origin.x, k = v0.y - ray.origin.y, l = v0.z - ray.origin.z;
        double eihf = e * i - h * f, gfdi = g * f - d * i, dheg = d * h - e * g;
        double akjb = a * k - j * b, jcal = j * c - a * l, blkc = b * l - k * c;
        double m = a * eihf + b * gfdi + c * dheg;
        if (m == 0) {
            return false;
        }
        double t = -(f * akjb + e * jcal + d * blkc) / m;
        double gamma = (i * akjb + h * jcal + g * blkc) / m;
        if (gamma < 0 || gamma > 1) {
            return false;
        }
        double beta = (j * eihf + k * gfdi + l * dheg) / m;
        if (beta < 0 || beta > 1 - gamma) {
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
