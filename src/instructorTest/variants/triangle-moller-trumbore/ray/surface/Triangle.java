package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Möller–Trumbore (1997): pvec, tvec, qvec and one reciprocal of the determinant. */
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
        if (u < 0 || u > 1) {
            return false;
        }
        Vec3 qvec = tvec.cross(edge1);
        double v = ray.direction.dot(qvec) * invDet;
        if (v < 0 || u + v > 1) {
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
        Vec3 texture = vt0.times(1 - u - v).plus(vt1.times(u)).plus(vt2.times(v));
        out.texU = texture.x;
        out.texV = texture.y;
        return true;
    }
}
