package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * A triangle with vertices v0, v1, v2. Its geometric normal is normalize((v1 − v0) × (v2 − v0));
 * when a mesh gives vertex normals n0, n1, n2, the shading normal is their barycentric blend.
 */
public class Triangle extends Surface {
    private Vec3 v0 = Vec3.ZERO;
    private Vec3 v1 = new Vec3(1, 0, 0);
    private Vec3 v2 = new Vec3(0, 1, 0);
    /** Vertex normals, or null for a flat triangle. */
    private Vec3 n0;
    private Vec3 n1;
    private Vec3 n2;
    private Vec3 faceNormal = new Vec3(0, 0, 1);

    public Triangle() {
    }

    public Triangle(Vec3 v0, Vec3 v1, Vec3 v2) {
        this.v0 = v0;
        this.v1 = v1;
        this.v2 = v2;
        complete();
    }

    /** A triangle whose normal is the barycentric blend of the given vertex normals. */
    public Triangle(Vec3 v0, Vec3 v1, Vec3 v2, Vec3 n0, Vec3 n1, Vec3 n2) {
        this(v0, v1, v2);
        this.n0 = n0;
        this.n1 = n1;
        this.n2 = n2;
    }

    public void setV0(Vec3 v0) {
        this.v0 = v0;
    }

    public void setV1(Vec3 v1) {
        this.v1 = v1;
    }

    public void setV2(Vec3 v2) {
        this.v2 = v2;
    }

    public Vec3 getV0() {
        return v0;
    }

    public Vec3 getV1() {
        return v1;
    }

    public Vec3 getV2() {
        return v2;
    }

    public boolean hasVertexNormals() {
        return n0 != null;
    }

    public Vec3 getFaceNormal() {
        return faceNormal;
    }

    @Override
    public Surface complete() {
        faceNormal = v1.minus(v0).cross(v2.minus(v0)).normalized();
        return this;
    }

    /** The unit normal at barycentric coordinates (beta, gamma): the face normal, or the blend of vertex normals. */
    public Vec3 normalAt(double beta, double gamma) {
        if (n0 == null) {
            return faceNormal;
        }
        Vec3 blend = n0.times(1 - beta - gamma).plus(n1.times(beta)).plus(n2.times(gamma)).normalized();
        return blend.lengthSquared() > 0 ? blend : faceNormal;
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        // TODO(Task 3): intersect the ray with this triangle by Cramer's rule.
        //   1) A point of the triangle is v0 + beta·(v1 − v0) + gamma·(v2 − v0). Setting it equal to
        //      p + t·d gives a 3×3 linear system in (beta, gamma, t):
        //        beta·(v0 − v1) + gamma·(v0 − v2) + t·d = v0 − p
        //   2) Solve it by Cramer's rule (Shirley & Marschner, Fundamentals of Computer Graphics §4.4.2).
        //      A zero determinant means the ray is parallel to the triangle: a miss.
        //   3) The ray hits when beta ≥ 0, gamma ≥ 0, beta + gamma ≤ 1 and ray.start < t < ray.end.
        //   4) On a hit fill out.t, out.location, out.normal = normalAt(beta, gamma), out.surface = this,
        //      out.beta and out.gamma, then return true. On a miss, return false and leave out alone.
        // BEGIN SOLUTION
        // Columns of the system's matrix: a = v0 − v1, b = v0 − v2, d; right-hand side r = v0 − p.
        double ax = v0.x - v1.x, ay = v0.y - v1.y, az = v0.z - v1.z;
        double bx = v0.x - v2.x, by = v0.y - v2.y, bz = v0.z - v2.z;
        double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
        double rx = v0.x - ray.origin.x, ry = v0.y - ray.origin.y, rz = v0.z - ray.origin.z;

        // Shared 2×2 minors of the last two columns keep Cramer's rule to a few multiplications.
        double byDzMinusBzDy = by * dz - bz * dy;
        double bzDxMinusBxDz = bz * dx - bx * dz;
        double bxDyMinusByDx = bx * dy - by * dx;
        double det = ax * byDzMinusBzDy + ay * bzDxMinusBxDz + az * bxDyMinusByDx;
        // No absolute epsilon: it would make small triangles vanish. Exactly parallel rays and
        // degenerate triangles give det == 0; NaN inputs fail the comparisons below.
        if (det == 0) {
            return false;
        }
        double invDet = 1 / det;
        double beta = (rx * byDzMinusBzDy + ry * bzDxMinusBxDz + rz * bxDyMinusByDx) * invDet;
        if (!(beta >= 0 && beta <= 1)) {
            return false;
        }
        double aYrZMinusRyAz = ay * rz - ry * az;
        double aZrXMinusRzAx = az * rx - rz * ax;
        double aXrYMinusRxAy = ax * ry - rx * ay;
        double gamma = (dz * aXrYMinusRxAy + dy * aZrXMinusRzAx + dx * aYrZMinusRyAz) * invDet;
        if (!(gamma >= 0 && beta + gamma <= 1)) {
            return false;
        }
        double t = -(bz * aXrYMinusRxAy + by * aZrXMinusRzAx + bx * aYrZMinusRyAz) * invDet;
        if (!(t > ray.start && t < ray.end)) {
            return false;
        }
        out.t = t;
        out.location = ray.pointAt(t);
        out.normal = normalAt(beta, gamma);
        out.surface = this;
        out.beta = beta;
        out.gamma = gamma;
        return true;
        // END SOLUTION
        // STUB: return false;
    }

    @Override
    public String toString() {
        return "Triangle[" + v0 + ", " + v1 + ", " + v2 + "]";
    }
}
