package ray.surface;

import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static ray.testing.RandomVectors.perpendicularUnit;
import static ray.testing.RandomVectors.randomUnit;
import static ray.testing.RandomVectors.randomVec;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.testing.Hints;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Bonus (extra credit) tests of Sphere.intersect on the hard numerical cases of docs/numerics.md,
 * where the textbook formula b² − 4ac, (−b ± √Δ)/2a loses its digits. Each test is one case, and its
 * failure message names the case, what went wrong and where to read about the fix. A failure costs
 * no regular points.
 *
 * <p>The expected answers need no oracle from outside this file: far-sphere rays are aimed a clear
 * margin inside or outside the silhouette, so hit or miss is certain; roots are computed exactly
 * from the same double inputs in BigDecimal; tangent rays are axis-aligned with dyadic sizes, so
 * their distance from the center is exactly the radius, or exactly one ulp off it. All rays are
 * seeded or enumerated, so every run sees the same cases.
 */
@Points(value = 1, bonus = true)
public class SphereHardCasesBonusTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    /** The relative error allowed in t against the exact root: about 4500 ulps (the solution's is at most 2 on these rays). */
    private static final double ROOT_TOLERANCE = 1e-12;

    /**
     * A unit sphere 1e7 away, and 400 rays from the origin aimed at points 1e-4 to 1e-3 inside or
     * outside its silhouette (half of each). The target's rounding (about 1e-9) and the line's tilt
     * change the distance of closest approach by less than 1e-8, so a ray aimed inside hits and one
     * aimed outside misses, with a margin of 1e-4. The textbook formula gets 200 of the 400 wrong
     * (48% of such rays in SphereSweep): b² and 4ac are about 4e28 and their difference, at most
     * about 8e11 here, is below their rounding (ulp(4e28) ≈ 9e12). The solution gets all 400 right
     * (and 0 of 7e6 wrong in SphereSweep).
     */
    @Test
    public void farSphereSilhouetteIsClassifiedExactly() {
        Random random = new Random(7_000_001);
        double distance = 1e7;
        int rays = 400;
        List<String> wrong = new ArrayList<>();
        for (int i = 0; i < rays; i++) {
            Vec3 toward = randomUnit(random);
            Vec3 center = toward.times(distance);
            Vec3 across = perpendicularUnit(toward, random);
            boolean inside = i % 2 == 0;
            double margin = 1e-4 + 9e-4 * random.nextDouble();
            double aim = inside ? 1 - margin : 1 + margin;
            Vec3 target = center.plus(across.times(aim));
            Sphere sphere = new Sphere(center, 1);
            Ray ray = new Ray(Vec3.ZERO, target);
            IntersectionRecord out = new IntersectionRecord();
            boolean hit = sphere.intersect(out, ray);
            // A hit is 1e7 − √(1 − aim²) away along a direction of length ≈ 1e7: t within 1e-6 of 1.
            boolean right = inside ? hit && Math.abs(out.t - 1) < 1e-6 : !hit;
            if (!right) {
                wrong.add(String.format(Locale.ROOT, "the ray toward %s, aimed %.2g %s the silhouette, %s", target, margin,
                        inside ? "inside" : "outside", inside ? (hit ? "hit at t = " + out.t + " instead of t ≈ 1" : "missed") : HitMessages.returnedTrue(out, false)));
            }
        }
        if (!wrong.isEmpty()) {
            fail("far sphere: rays grazing the silhouette of a unit sphere 1e7 away are misclassified (" + wrong.size() + " of "
                    + rays + " hit/miss wrong; e.g. " + wrong.get(0) + ")" + Hints.fix(": b² − 4ac cancels catastrophically when b² and 4ac"
                    + " are both about 4e28; compute the discriminant from the closest-approach vector"
                    + " (Ray Tracing Gems ch. 7, docs/numerics.md)"));
        }
    }

    /**
     * 200 rays starting 0.25 to 1.7 outside spheres of radius 1e5 to 1e6 (integer centers within 1e6
     * of the origin) and heading in, at least 60° from grazing, in random directions. The origins lie
     * on a 1/64 grid, so that o − c and c = (o − c)·(o − c) − r² are exact in double and only the
     * formula's own rounding counts; the expected root is computed exactly from the same doubles
     * (BigDecimal, 60 digits). The textbook near root (−b − √Δ)/2a subtracts two numbers of about 2R
     * to get one of about 2: it loses log₂(R) bits, up to 1.3e6 ulps on these rays (2.9e6 at R = 1e6
     * in SphereSweep), and 185 of the 200 miss the 1e-12 tolerance (about 4500 ulps). The stable
     * form c/q is within 2 ulps on every one of them.
     */
    @Test
    public void rayJustOutsideAHugeSphereGetsTheNearRootToTwelveDigits() {
        Random random = new Random(7_000_002);
        int rays = 200;
        RootErrors errors = new RootErrors();
        for (int i = 0; i < rays; i++) {
            errors.check(nearSurfaceRay(random, -1), false);
        }
        if (errors.count > 0) {
            fail(String.format(Locale.ROOT, "huge sphere: for rays starting within about a unit of a sphere of radius 1e5…1e6,"
                    + " %d of %d near roots were off by more than %.0e relative (worst: %s)."
                    + Hints.fix(" In (−b − √Δ)/2a, −b and √Δ are both about 2R and nearly cancel; take the near root as c/q with"
                    + " q = −(b + sign(b)·√Δ)/2, which never subtracts (the stable quadratic, Numerical Recipes §5.6;"
                    + " Ray Tracing Gems ch. 7)"), errors.count, rays, ROOT_TOLERANCE, errors.worst));
        }
    }

    /**
     * Rays that start inside a sphere must hit its far root, ahead of the origin. Two kinds, 100 each:
     * from deep inside (within half the radius of the center; radii 1e-3 to 1e3), and from 0.25 to
     * 1.7 inside a sphere of radius 1e5 to 1e6, heading out (built as in the huge-sphere case). The
     * first catches code that takes the near root, which is negative from inside; the second, the
     * cancellation in the textbook far root (−b + √Δ)/2a when b > 0, the inside twin of the
     * huge-sphere case: the textbook formula gets all deep rays right and misses the 1e-12 tolerance
     * on 95 of the 100 shallow ones (up to 7.5e5 ulps). The expected roots are computed exactly
     * (BigDecimal); the solution is within 2 ulps on all 200.
     */
    @Test
    public void rayFromInsideGetsTheFarRootAheadOfIt() {
        Random random = new Random(7_000_003);
        int perKind = 100;
        RootErrors deep = new RootErrors();
        RootErrors shallow = new RootErrors();
        for (int i = 0; i < perKind; i++) {
            Vec3 center = randomVec(random, 100);
            double radius = Math.pow(10, -3 + 6 * random.nextDouble());
            Vec3 origin = center.plus(randomUnit(random).times(0.5 * radius * random.nextDouble()));
            Vec3 d = randomUnit(random).times(Math.pow(10, -2 + 4 * random.nextDouble()));
            deep.check(new Case(new Sphere(center, radius), new Ray(origin, d)), true);
        }
        for (int i = 0; i < perKind; i++) {
            shallow.check(nearSurfaceRay(random, 1), true);
        }
        if (deep.count > 0) {
            fail("ray from inside: " + deep.count + " of " + perKind + " rays from deep inside a sphere did not hit the far root"
                    + " (e.g. " + deep.worst + ")." + Hints.fix(" From inside, the near root is negative (behind the origin):"
                    + " take the smallest root with start < t < end, which is the far one"));
        }
        if (shallow.count > 0) {
            fail(String.format(Locale.ROOT, "ray from inside: %d of %d rays starting just inside a sphere of radius 1e5…1e6 and"
                    + " heading out got the far root wrong by more than %.0e relative (worst: %s)" + Hints.fix(": in (−b + √Δ)/2a with b > 0,"
                    + " −b and √Δ nearly cancel; take that root as c/q with q = −(b + sign(b)·√Δ)/2 (the stable quadratic,"
                    + " Numerical Recipes §5.6; Ray Tracing Gems ch. 7)"), shallow.count, perKind, ROOT_TOLERANCE, shallow.worst));
        }
    }

    /** A sphere and a ray at it. */
    private record Case(Sphere sphere, Ray ray) {
    }

    /**
     * A ray starting 0.25 to 1.7 from the surface of a sphere of integer radius 1e5…1e6 around an
     * integer center, outside and heading in (side −1) or inside and heading out (side +1), at least
     * 60° from grazing; the origin is on a 1/64 grid, so o − c and (o − c)·(o − c) − r² are exact.
     */
    private static Case nearSurfaceRay(Random random, int side) {
        double radius = 100_000 + random.nextInt(900_001);
        Vec3 center = new Vec3(random.nextInt(2_000_001) - 1_000_000, random.nextInt(2_000_001) - 1_000_000,
                random.nextInt(2_000_001) - 1_000_000);
        Vec3 out = randomUnit(random);
        Vec3 origin = onGrid(center.plus(out.times(radius - side * (0.25 + 1.45 * random.nextDouble()))));
        Vec3 d;
        do {
            d = randomUnit(random);
        } while (side * d.dot(out) < 0.5);
        return new Case(new Sphere(center, radius), new Ray(origin, d.times(0.5 + random.nextDouble())));
    }

    /** Counts rays whose t is not within ROOT_TOLERANCE (relative) of the exact root, and keeps the worst. */
    private static final class RootErrors {
        int count;
        String worst = "";
        private double worstError;

        void check(Case c, boolean far) {
            double exact = exactRoot(c.sphere(), c.ray(), far);
            IntersectionRecord out = new IntersectionRecord();
            boolean hit = c.sphere().intersect(out, c.ray());
            double error = hit ? Math.abs(out.t - exact) / exact : Double.POSITIVE_INFINITY;
            if (!(error <= ROOT_TOLERANCE)) {
                count++;
                if (count == 1 || error > worstError) {
                    worstError = error;
                    worst = String.format(Locale.ROOT, "%s at %s: %s, the exact %s root is t = %s", c.ray(), c.sphere(),
                            hit ? "t = " + out.t + String.format(Locale.ROOT, " (%.0f ulps off)", Math.abs(out.t - exact) / Math.ulp(exact))
                                    : "missed",
                            far ? "far" : "near", exact);
                }
            }
        }
    }

    /**
     * The root of |o + t·d − c|² = r² for the exact double inputs: with b' = d·(o − c),
     * t = (−b' ∓ √(b'² − (d·d)((o − c)·(o − c) − r²)))/(d·d), computed in BigDecimal (products and
     * sums exact, the square root to 60 digits) and then rounded to double.
     */
    private static double exactRoot(Sphere sphere, Ray ray, boolean far) {
        BigDecimal[] d = exact(ray.direction);
        BigDecimal[] o = exact(ray.origin);
        BigDecimal[] c = exact(sphere.getCenter());
        BigDecimal[] f = {o[0].subtract(c[0]), o[1].subtract(c[1]), o[2].subtract(c[2])};
        BigDecimal a = dot(d, d);
        BigDecimal halfB = dot(f, d);
        BigDecimal r = new BigDecimal(sphere.getRadius());
        BigDecimal quarterDiscriminant = halfB.multiply(halfB).subtract(a.multiply(dot(f, f).subtract(r.multiply(r))));
        if (quarterDiscriminant.signum() < 0) {
            throw new IllegalStateException("the test built a ray that misses: " + ray);
        }
        MathContext digits = new MathContext(60);
        BigDecimal root = quarterDiscriminant.sqrt(digits);
        return (far ? halfB.negate().add(root) : halfB.negate().subtract(root)).divide(a, digits).doubleValue();
    }

    private static BigDecimal[] exact(Vec3 v) {
        return new BigDecimal[] {new BigDecimal(v.x), new BigDecimal(v.y), new BigDecimal(v.z)};
    }

    private static BigDecimal dot(BigDecimal[] u, BigDecimal[] v) {
        return u[0].multiply(v[0]).add(u[1].multiply(v[1])).add(u[2].multiply(v[2]));
    }

    private static Vec3 onGrid(Vec3 v) {
        return new Vec3(Math.rint(v.x * 64) / 64, Math.rint(v.y * 64) / 64, Math.rint(v.z * 64) / 64);
    }

    /**
     * Tangent rays. 216 axis-aligned rays whose distance from the center is exactly the radius
     * (dyadic radii and centers, so that the geometry is exact in double) must touch the sphere at
     * the exact tangent point, with the exact axis normal. 94 rays passing one ulp inside must hit
     * and 112 rays one ulp outside must miss (only nudges that survive o − c exactly are used): with
     * the origin 10 or more radii away, the textbook formula rounds the ulp away in (p − c)·(p − c)
     * and reports all 112 outside rays as hits (Δ = 0); the closest-approach discriminant r² − l·l
     * keeps it. Then 2,000 random rays within 4 ulps of tangency: each must be a clean hit (finite
     * t > 0, a point on the sphere, a unit normal) or a clean miss (the record untouched), never NaN;
     * code that takes the square root of a slightly negative discriminant fails here. The solution
     * gets every one of these right.
     */
    @Test
    public void tangentRaysHitOrMissCleanly() {
        Problems problems = new Problems();
        double[] radii = {0.5, 1, 0.75, 2, 1024, 0x1p-10};
        Vec3[] centers = {Vec3.ZERO, new Vec3(3, -2, 1.5), new Vec3(-1024, 512, 7)};
        double[] lengths = {0.5, 1, 2};
        int nudged = 0;
        for (double r : radii) {
            for (Vec3 c : centers) {
                for (int along = 0; along < 3; along++) {
                    for (int offset = 0; offset < 3; offset++) {
                        for (int sign = -1; sign <= 1 && offset != along; sign += 2) {
                            // Along axis `along`, passing the center at distance r along axis `offset`: the
                            // ray touches c + sign·r·e(offset) after the distance `far`. All of it is exact.
                            double length = lengths[(along + offset + (sign + 1) / 2) % 3];
                            double far = r * (10 + along + 3 * offset);
                            Vec3 d = axis(along, sign * length);
                            Sphere sphere = new Sphere(c, r);
                            Vec3 touch = c.plus(axis(offset, sign * r));
                            checkExactTangent(sphere, new Ray(touch.minus(axis(along, sign * far)), d), touch,
                                    axis(offset, sign), far / length, problems);
                            // One ulp inside and one ulp outside, where o − c keeps the nudge exactly.
                            for (double passesAt : new double[] {Math.nextDown(r), Math.nextUp(r)}) {
                                Vec3 o = c.plus(axis(offset, sign * passesAt)).minus(axis(along, sign * far));
                                BigDecimal exactOffset = new BigDecimal(o.get(offset)).subtract(new BigDecimal(c.get(offset)));
                                if (o.minus(c).get(offset) == sign * passesAt
                                        && exactOffset.abs().compareTo(new BigDecimal(passesAt)) == 0) {
                                    nudged++;
                                    checkNudged(sphere, new Ray(o, d), passesAt < r, problems);
                                }
                            }
                        }
                    }
                }
            }
        }
        assertTrue("the test's own one-ulp cases were not built (" + nudged + " of 206)", nudged == 206);
        Random random = new Random(7_000_004);
        for (int i = 0; i < 2000; i++) {
            Vec3 c = randomVec(random, 10);
            double r = Math.pow(10, -1 + 2 * random.nextDouble());
            Vec3 dir = randomUnit(random);
            Vec3 across = perpendicularUnit(dir, random);
            double passesAt = r * (1 + (random.nextInt(9) - 4) * 0x1p-52);
            Vec3 origin = c.plus(across.times(passesAt)).minus(dir.times(r * (2 + 20 * random.nextDouble())));
            checkClean(new Sphere(c, r), new Ray(origin, dir.times(0.5 + random.nextDouble())), problems);
        }
        if (!problems.byKind.isEmpty()) {
            fail("tangent ray: rays that graze a sphere went wrong " + problems.summary());
        }
    }

    private static void checkExactTangent(Sphere sphere, Ray ray, Vec3 touch, Vec3 normal, double t, Problems problems) {
        IntersectionRecord out = new IntersectionRecord();
        if (!sphere.intersect(out, ray)) {
            problems.add("exactly tangent rays missed", ray + " touches " + sphere + " at exactly one point, " + touch
                    + Hints.fix(" (b² − 4ac = 0 exactly)") + ", but missed" + Hints.fix(": a discriminant of exactly 0 is a hit"));
        } else if (!sound(out) || Math.abs(out.t - t) > 1e-12 * t
                || out.location.minus(touch).length() > 1e-12 * (1 + touch.maxAbs()) || out.normal.minus(normal).length() > 1e-12) {
            problems.add("exactly tangent rays hit the wrong point", ray + " touches " + sphere + " at " + touch + " (t = " + t
                    + ", normal " + normal + "), but the hit was t = " + out.t + ", location " + out.location + ", normal " + out.normal);
        }
    }

    private static void checkNudged(Sphere sphere, Ray ray, boolean inside, Problems problems) {
        IntersectionRecord out = Records.sentinel(sphere);
        IntersectionRecord before = Records.copyOf(out);
        boolean hit = sphere.intersect(out, ray);
        if (inside && !hit) {
            problems.add("rays one ulp inside missed", ray + " passes one ulp inside the silhouette of " + sphere + " but missed");
        } else if (inside && !sound(out)) {
            problems.add("rays one ulp inside hit with NaN or a bad normal", ray + " passes one ulp inside " + sphere
                    + ": the hit has NaN, infinity or a normal that is not unit: t = " + out.t + ", location " + out.location
                    + ", normal " + out.normal);
        } else if (!inside && hit) {
            problems.add("rays one ulp outside hit", ray + " passes one ulp outside " + sphere + " but was reported as a hit at t = "
                    + out.t + Hints.fix(": (p − c)·(p − c) and b² round the ulp away, so b² − 4ac comes out 0; compute the discriminant as"
                    + " r² − l·l from the closest-approach vector l (Ray Tracing Gems ch. 7, docs/numerics.md)"));
        } else if (!inside && !untouched(before, out)) {
            problems.add("misses changed the record", ray + " misses " + sphere + " but the record was changed");
        }
    }

    private static void checkClean(Sphere sphere, Ray ray, Problems problems) {
        IntersectionRecord out = Records.sentinel(sphere);
        IntersectionRecord before = Records.copyOf(out);
        String what = ray + ", within 4 ulps of tangency to " + sphere;
        if (sphere.intersect(out, ray)) {
            double r = sphere.getRadius();
            double offSphere = Math.abs(out.location == null ? Double.NaN : out.location.minus(sphere.getCenter()).length() - r);
            if (!sound(out) || !(out.t > 0) || !(offSphere <= 1e-9 * (r + sphere.getCenter().maxAbs()))) {
                problems.add("near-tangent hits were not clean", what + ", hit at t = " + out.t + ", location " + out.location
                        + ", normal " + out.normal + ": a hit needs a finite t > 0, a point on the sphere and a unit normal"
                        + Hints.fix(" (no NaN: check the discriminant before its square root, and test start < t < end, which NaN fails)"));
            }
        } else if (!untouched(before, out)) {
            problems.add("misses changed the record", what + ", missed but changed the record (t = " + out.t + ")");
        }
    }

    /** What went wrong, by kind: how often, and the first example of each. */
    private static final class Problems {
        final Map<String, List<String>> byKind = new LinkedHashMap<>();

        void add(String kind, String example) {
            byKind.computeIfAbsent(kind, k -> new ArrayList<>()).add(example);
        }

        /** "in 2 ways: (1) 112 rays one ulp outside hit, e.g. ...; (2) ...". */
        String summary() {
            StringBuilder s = new StringBuilder("in " + byKind.size() + (byKind.size() == 1 ? " way:" : " ways:"));
            int n = 1;
            for (Map.Entry<String, List<String>> e : byKind.entrySet()) {
                s.append(n > 1 ? "; " : " ").append('(').append(n++).append(") ").append(e.getValue().size()).append(' ')
                        .append(e.getKey()).append(", e.g. ").append(e.getValue().get(0));
            }
            return s.toString();
        }
    }

    /** Finite t, location and normal, and a unit normal. */
    private static boolean sound(IntersectionRecord out) {
        return Double.isFinite(out.t) && out.location != null && out.location.isFinite() && out.normal != null
                && out.normal.isFinite() && Math.abs(out.normal.length() - 1) < 1e-9;
    }

    private static boolean untouched(IntersectionRecord before, IntersectionRecord after) {
        return Double.compare(before.t, after.t) == 0 && before.location == after.location && before.normal == after.normal
                && before.surface == after.surface;
    }

    private static Vec3 axis(int axis, double value) {
        return new Vec3(axis == 0 ? value : 0, axis == 1 ? value : 0, axis == 2 ? value : 0);
    }
}
