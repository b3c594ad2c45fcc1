package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * A triangle with vertices v0, v1, v2 (kept, with any vertex normals and texture coordinates
 * vt0, vt1, vt2, by TriangleSurface). Its
 * geometric normal is normalize((v1 − v0) × (v2 − v0)); normalAt(beta, gamma) is the normal to
 * report, the blend of the vertex normals when a mesh gives them.
 */
public class Triangle extends TriangleSurface {

    public Triangle() {
    }

    public Triangle(Vec3 v0, Vec3 v1, Vec3 v2) {
        super(v0, v1, v2);
    }

    /** A triangle whose normal is the barycentric blend of the given vertex normals. */
    public Triangle(Vec3 v0, Vec3 v1, Vec3 v2, Vec3 n0, Vec3 n1, Vec3 n2) {
        super(v0, v1, v2, n0, n1, n2);
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        // TODO(Task 3): intersect the ray with this triangle.
        //   Return whether the ray meets the triangle, and on a hit fill out: its t, its location, the normal
        //   from normalAt, this surface, out.beta and out.gamma, and the texture coordinates. On a miss leave
        //   out exactly as it was. Any correct method earns the points.
        //   Conventions (the reference images depend on them):
        //   - The hit counts only for ray.start < t < ray.end, both ends open, with t the ray's own
        //     parameter (its direction is not unit length).
        //   - beta is the weight of v1 and gamma the weight of v2 (v0 gets the rest); the triangle's edges
        //     and corners belong to it, and a ray in its plane or parallel to it misses.
        //   - The texture coordinates are vt0, vt1 and vt2 blended with those weights: out.texU is the
        //     blend's x and out.texV its y.
        // HINTS steps
        //   1) Write a point of the triangle with two barycentric weights and set it equal to a point of the
        //      ray: three equations (one per axis) in three unknowns.
        //   2) Solve them (the lecture's way is Cramer's rule); when they have no single solution the ray is
        //      parallel to the triangle and misses.
        //   3) Check that the point lies inside the triangle and t inside the ray's segment.
        //   4) On a hit fill the record as above and return true.
        //   5) Blend the vertices' texture coordinates with the weights you found.
        // HINTS formulas
        //   The lecture's method is Cramer's rule, as below.
        //   1) A point of the triangle is v0 + beta·(v1 − v0) + gamma·(v2 − v0). Setting it equal to
        //      p + t·d gives a 3×3 linear system in (beta, gamma, t):
        //        beta·(v0 − v1) + gamma·(v0 − v2) + t·d = v0 − p
        //   2) Solve it by Cramer's rule (Shirley & Marschner, Fundamentals of Computer Graphics §4.4.2).
        //      A zero determinant means the ray is parallel to the triangle: a miss.
        //   3) The ray hits when beta ≥ 0, gamma ≥ 0, beta + gamma ≤ 1 and ray.start < t < ray.end.
        //   4) On a hit fill out.t, out.location, out.normal = normalAt(beta, gamma), out.surface = this,
        //      out.beta and out.gamma, then return true. On a miss, return false and leave out alone.
        //   5) Also fill the texture coordinates, blended like the location: with
        //      vt = (1 − beta − gamma)·vt0 + beta·vt1 + gamma·vt2, out.texU = vt.x and out.texV = vt.y.
        // END HINTS
        // BEGIN SOLUTION
        // Not Cramer's rule but the watertight test of Woop, Benthin and Wald, "Watertight
        // Ray/Triangle Intersection", JCGT 2(1), 2013: a ray aimed exactly at an edge or vertex
        // shared by two triangles hits at least one of them, which Cramer's rule does not promise.
        if (isDegenerate()) {
            return false;
        }
        // Name the axes so that the ray's largest direction component is z, by a cyclic shift that
        // keeps the frame right-handed. (The paper also swaps x and y when that component is
        // negative, to keep the winding for back-face culling; this test is two-sided and divides
        // by det, so a mirror, which negates u, v, w and det together, changes nothing.)
        Vec3 p = ray.origin;
        Vec3 d = ray.direction;
        int kz = Math.abs(d.x) >= Math.abs(d.y) && Math.abs(d.x) >= Math.abs(d.z) ? 0 : Math.abs(d.y) >= Math.abs(d.z) ? 1 : 2;
        // Vertices relative to the ray origin, in the shifted axes (one row per shift).
        double a0 = v0.x - p.x, a1 = v0.y - p.y, a2 = v0.z - p.z;
        double b0 = v1.x - p.x, b1 = v1.y - p.y, b2 = v1.z - p.z;
        double c0 = v2.x - p.x, c1 = v2.y - p.y, c2 = v2.z - p.z;
        double ax, ay, az, bx, by, bz, cx, cy, cz;
        if (kz == 2) {
            ax = a0; ay = a1; az = a2; bx = b0; by = b1; bz = b2; cx = c0; cy = c1; cz = c2;
        } else if (kz == 0) {
            ax = a1; ay = a2; az = a0; bx = b1; by = b2; bz = b0; cx = c1; cy = c2; cz = c0;
        } else {
            ax = a2; ay = a0; az = a1; bx = b2; by = b0; bz = b1; cx = c2; cy = c0; cz = c1;
        }
        // Shear the vertices so that the ray becomes the +z axis through the origin. Each vertex's
        // 2D position depends on that vertex and the ray only, so triangles that share it agree.
        // The renamed (x, y, z) is (x, y, z) for kz = 2, (y, z, x) for kz = 0 and (z, x, y) for kz = 1.
        double sz = 1 / d.get(kz);
        double sx = d.get((kz + 1) % 3) * sz;
        double sy = d.get((kz + 2) % 3) * sz;
        ax -= sx * az;
        ay -= sy * az;
        bx -= sx * bz;
        by -= sy * bz;
        cx -= sx * cz;
        cy -= sy * cz;
        // 2D edge functions: u for edge v1v2, v for v2v0, w for v0v1; each is twice the signed area
        // of the sub-triangle (ray, edge) and so the weight of the opposite vertex. The same edge
        // walked backwards by a neighbor gives exactly −u (same products, swapped subtraction), so
        // two neighbors always agree on which side of their shared edge the ray passes.
        double u = cx * by - cy * bx;
        double v = ax * cy - ay * cx;
        // Most rays miss most triangles: reject on two edges before computing the third.
        if ((u < 0 && v > 0) || (u > 0 && v < 0)) {
            return false;
        }
        double w = bx * ay - by * ax;
        // A zero may be a rounded-away tiny value; its true sign decides which side the ray is on.
        if (u == 0 || v == 0 || w == 0) {
            u = u == 0 ? differenceOfProducts(cx, by, cy, bx) : u;
            v = v == 0 ? differenceOfProducts(ax, cy, ay, cx) : v;
            w = w == 0 ? differenceOfProducts(bx, ay, by, ax) : w;
        }
        // Inside (edges and vertices included) when all three have one sign; NaN fails both tests.
        if (!((u >= 0 && v >= 0 && w >= 0) || (u <= 0 && v <= 0 && w <= 0))) {
            return false;
        }
        double det = u + v + w;
        if (det == 0) {
            return false; // the ray lies in the triangle's plane, or passes through it edge-on
        }
        // A ray exactly parallel to the plane (beside it or in it) projects the triangle onto a
        // segment, but the shear's rounding can leave a sliver around the ray, with a det of
        // rounding size: below 512·2⁻⁵³·m², m the largest vertex coordinate relative to the ray
        // origin (a rough error bound is 250·2⁻⁵³·m²; in-plane rays measured at most 1.2·2⁻⁵³·m²).
        // Only such a det needs the exact test.
        double m = Math.max(largestMagnitude(a0, a1, a2), Math.max(largestMagnitude(b0, b1, b2), largestMagnitude(c0, c1, c2)));
        if (Math.abs(det) <= PARALLEL_BOUND * m * m && parallelToPlane(d)) {
            return false;
        }
        // The hit's z in the sheared frame (z scaled by sz), interpolated with the unnormalized
        // weights, is det·t.
        double t = (u * (sz * az) + v * (sz * bz) + w * (sz * cz)) / det;
        if (!(t > ray.start && t < ray.end)) {
            return false;
        }
        // An infinite direction gives sz = 0 and so t = 0, which a segment starting below 0 accepts,
        // at the point origin + 0·∞ = NaN: only a finite location makes a hit.
        Vec3 location = ray.pointAt(t);
        if (!location.isFinite()) {
            return false;
        }
        fill(out, t, location, v / det, w / det);
        return true;
        // END SOLUTION
        // STUB: return false;
    }
    // BEGIN SOLUTION

    /** Records a hit with barycentrics beta (the weight of v1) and gamma (the weight of v2). */
    private void fill(IntersectionRecord out, double t, Vec3 location, double beta, double gamma) {
        out.t = t;
        out.location = location;
        out.normal = normalAt(beta, gamma);
        out.surface = this;
        out.beta = beta;
        out.gamma = gamma;
        double alpha = 1 - beta - gamma;
        out.texU = alpha * vt0.x + beta * vt1.x + gamma * vt2.x;
        out.texV = alpha * vt0.y + beta * vt1.y + gamma * vt2.y;
    }

    /** 512·2⁻⁵³: see the parallel test in intersect. */
    private static final double PARALLEL_BOUND = 0x1p-44;

    /**
     * Whether d is exactly parallel to the triangle's plane, d·((v1 − v0) × (v2 − v0)) = 0, in exact
     * arithmetic (BigDecimal holds every product of doubles exactly). Slow, but only asked when the
     * double computation cannot tell, which rendering practically never reaches. A non-finite d
     * counts as parallel: it has no finite hit anyway, and BigDecimal cannot hold it. (The vertices
     * are finite: complete() marks any other triangle degenerate.)
     */
    private boolean parallelToPlane(Vec3 d) {
        if (!d.isFinite()) {
            return true;
        }
        var e1x = exact(v1.x).subtract(exact(v0.x));
        var e1y = exact(v1.y).subtract(exact(v0.y));
        var e1z = exact(v1.z).subtract(exact(v0.z));
        var e2x = exact(v2.x).subtract(exact(v0.x));
        var e2y = exact(v2.y).subtract(exact(v0.y));
        var e2z = exact(v2.z).subtract(exact(v0.z));
        var nx = e1y.multiply(e2z).subtract(e1z.multiply(e2y));
        var ny = e1z.multiply(e2x).subtract(e1x.multiply(e2z));
        var nz = e1x.multiply(e2y).subtract(e1y.multiply(e2x));
        return exact(d.x).multiply(nx).add(exact(d.y).multiply(ny)).add(exact(d.z).multiply(nz)).signum() == 0;
    }

    private static java.math.BigDecimal exact(double x) {
        return new java.math.BigDecimal(x);
    }

    private static double largestMagnitude(double x, double y, double z) {
        return Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
    }

    /**
     * p·q − r·s by Kahan's 2×2 determinant: the rounding error of r·s, which an FMA finds exactly, is
     * added back. Its relative error is at most 2⁻⁵² (Jeannerod, Louvet and Muller, Math. Comp. 82,
     * 2013), so barring underflow its sign is exact and it is zero only when p·q = r·s exactly.
     */
    private static double differenceOfProducts(double p, double q, double r, double s) {
        double rs = r * s;
        double roundingOfRs = Math.fma(-r, s, rs);
        return Math.fma(p, q, -rs) + roundingOfRs;
    }
    // END SOLUTION
}
