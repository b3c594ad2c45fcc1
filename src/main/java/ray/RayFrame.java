package ray;

import ray.math.Vec3;

/**
 * Constants of a ray that intersection tests need and that depend on its direction only, so that
 * a ray computes them once (see {@link Ray#frame()}) rather than once per surface it is tested
 * against; a Group tests each ray against every child, so this saves a square root and a division
 * per sphere test, and a division and the axis choice per triangle test:
 * <ul>
 * <li>the unit direction d/|d| (the robust sphere test's closest-approach vector);</li>
 * <li>for the watertight ray–triangle test (Woop, Benthin and Wald, "Watertight Ray/Triangle
 * Intersection", JCGT 2(1), 2013), the axis kz of the direction's largest component, and the shear
 * (sx, sy, sz) that, after a cyclic renaming of the axes puts kz last, maps the direction to
 * (0, 0, 1).</li>
 * </ul>
 */
public final class RayFrame {
    /** 0, 1 or 2: the axis of the direction's largest |component| (x on ties with y or z, y on ties with z). */
    public final int kz;
    public final double sx;
    public final double sy;
    public final double sz;
    /** d·(1/√(d·d)); not finite when d is zero or not finite, which the tests reject first. */
    public final Vec3 unitDirection;

    RayFrame(Vec3 d) {
        double x = Math.abs(d.x);
        double y = Math.abs(d.y);
        double z = Math.abs(d.z);
        kz = x >= y && x >= z ? 0 : y >= z ? 1 : 2;
        // The renamed (x, y, z) is (x, y, z) for kz = 2, (y, z, x) for kz = 0 and (z, x, y) for kz = 1.
        double dx = d.get((kz + 1) % 3);
        double dy = d.get((kz + 2) % 3);
        sz = 1 / d.get(kz);
        sx = dx * sz;
        sy = dy * sz;
        unitDirection = d.times(1 / Math.sqrt(d.dot(d)));
    }
}
