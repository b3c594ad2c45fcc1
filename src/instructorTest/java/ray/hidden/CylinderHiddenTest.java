package ray.hidden;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static ray.surface.HitAsserts.assertHit;
import static ray.surface.HitAsserts.assertHitAt;
import static ray.surface.HitAsserts.assertMiss;
import static ray.testing.Asserts.v;

import java.util.Locale;
import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Cylinder;
import ray.testing.Points;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden extra-credit cylinder cases, seeded: rays aimed at random points of the side and caps
 * from outside, rays from inside, lines that pass the axis farther than the radius, and a record
 * that already holds a hit does not stop a closer one.
 *
 * <p>The oracle needs no cylinder code of its own: a capped cylinder is convex, so a ray that
 * reaches a surface point P with its direction against P's outward normal enters the solid at P,
 * and nothing before P on the ray is on the cylinder. So a ray started a distance s before P along
 * d must hit at t = s, at P, with P's normal. Points are kept a margin away from the rims, where the
 * side and a cap meet and either normal would be fair.
 */
@Points(value = 1, visibility = Visibility.HIDDEN)
public class CylinderHiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final int RAYS = 300;

    /** A random cylinder: center within 10 of the origin, radius and height from 0.1 to 10. */
    private static Cylinder randomCylinder(Random random) {
        Vec3 center = v(20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10);
        return new Cylinder(center, 0.1 + 9.9 * random.nextDouble(), 0.1 + 9.9 * random.nextDouble());
    }

    private static Vec3 randomUnit(Random random) {
        while (true) {
            Vec3 p = v(2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1);
            double l = p.length();
            if (l > 0.1 && l <= 1) {
                return p.times(1 / l);
            }
        }
    }

    @Test
    public void raysAimedAtTheSideOrACapFromOutsideHitThere() {
        Random random = new Random(6_000_001);
        for (int i = 0; i < RAYS; i++) {
            Cylinder cylinder = randomCylinder(random);
            Vec3 c = cylinder.getCenter();
            double r = cylinder.getRadius();
            double h = cylinder.getHeight();
            Vec3 point;
            Vec3 normal;
            int part = i % 3; // side, top, bottom in turn
            if (part == 0) {
                double angle = 2 * Math.PI * random.nextDouble();
                normal = v(Math.sin(angle), 0, Math.cos(angle));
                point = c.plus(v(r * normal.x, h * (0.05 + 0.9 * random.nextDouble()), r * normal.z));
            } else {
                double angle = 2 * Math.PI * random.nextDouble();
                double along = r * 0.9 * Math.sqrt(random.nextDouble());
                normal = v(0, part == 1 ? 1 : -1, 0);
                point = c.plus(v(along * Math.sin(angle), part == 1 ? h : 0, along * Math.cos(angle)));
            }
            Vec3 d;
            do {
                d = randomUnit(random);
            } while (!(d.dot(normal) < -0.2));
            double length = 0.01 + 100 * random.nextDouble();
            d = d.times(length);
            double s = 0.1 + 5 * random.nextDouble();
            Ray ray = new Ray(point.minus(d.times(s)), d);
            IntersectionRecord out = new IntersectionRecord();
            String what = String.format(Locale.ROOT, "%s, the ray %s + t·%s aimed at %s on its %s", cylinder, ray.origin, d, point,
                    part == 0 ? "side" : part == 1 ? "top cap" : "bottom cap");
            double scale = c.maxAbs() + r + h;
            assertHitAt(what, cylinder, out, ray, s, 1e-9 * s * Math.max(1, scale / (s * length)));
            assertTrue(what + ": location " + out.location + " is not the aimed point", out.location.minus(point).maxAbs() < 1e-9 * scale);
            assertTrue(what + ": normal " + out.normal + ", expected the unit outward " + normal,
                    out.normal.minus(normal).maxAbs() < 1e-9);
            assertTrue(what + ": out.surface", out.surface == cylinder);
        }
    }

    @Test
    public void raysFromInsideLeaveThroughTheSurfaceWithAnOutwardNormal() {
        Random random = new Random(6_000_002);
        for (int i = 0; i < RAYS; i++) {
            Cylinder cylinder = randomCylinder(random);
            Vec3 c = cylinder.getCenter();
            double r = cylinder.getRadius();
            double h = cylinder.getHeight();
            double angle = 2 * Math.PI * random.nextDouble();
            double along = r * 0.8 * Math.sqrt(random.nextDouble());
            Vec3 origin = c.plus(v(along * Math.sin(angle), h * (0.1 + 0.8 * random.nextDouble()), along * Math.cos(angle)));
            Vec3 d = randomUnit(random).times(0.1 + 10 * random.nextDouble());
            IntersectionRecord out = new IntersectionRecord();
            String what = String.format(Locale.ROOT, "%s, the ray %s + t·%s from inside", cylinder, origin, d);
            assertHit(what + ", at the wall it leaves through", cylinder, out, new Ray(origin, d));
            assertTrue(what + ": t = " + out.t + " must be positive", out.t > 0);
            Vec3 local = out.location.minus(c);
            double fromAxis = Math.hypot(local.x, local.z);
            double tolerance = 1e-9 * (c.maxAbs() + r + h);
            boolean onSide = Math.abs(fromAxis - r) < tolerance && local.y > -tolerance && local.y < h + tolerance;
            boolean onCap = (Math.abs(local.y) < tolerance || Math.abs(local.y - h) < tolerance) && fromAxis < r + tolerance;
            if (!onSide && !onCap) {
                fail(what + ": the reported location " + out.location + " is not on the cylinder");
            }
            assertTrue(what + ": the normal " + out.normal + " must point outward, along the ray leaving", out.normal.dot(d) > 0);
            assertEquals(what + ": the normal must have unit length", 1, out.normal.length(), 1e-9);
        }
    }

    @Test
    public void linesFartherFromTheAxisThanTheRadiusMiss() {
        Random random = new Random(6_000_003);
        Cylinder hitCheck = new Cylinder(Vec3.ZERO, 1, 1);
        assertHit("(0,0.5,5) toward −z at the cylinder of radius 1 and height 1 at the origin", hitCheck, new IntersectionRecord(),
                new Ray(v(0, 0.5, 5), v(0, 0, -1)));
        for (int i = 0; i < RAYS; i++) {
            Cylinder cylinder = randomCylinder(random);
            Vec3 c = cylinder.getCenter();
            double r = cylinder.getRadius();
            // A horizontal-ish line passing the axis at 1.05 to 3 radii: its xz projection never comes within r.
            double angle = 2 * Math.PI * random.nextDouble();
            Vec3 across = v(Math.sin(angle), 0, Math.cos(angle));
            Vec3 alongLine = v(across.z, 0, -across.x);
            double distance = r * (1.05 + 1.95 * random.nextDouble());
            Vec3 passing = c.plus(across.times(distance)).plus(v(0, cylinder.getHeight() * random.nextDouble(), 0));
            Vec3 d = alongLine.plus(v(0, 0.5 * random.nextDouble() - 0.25, 0)).times(0.5 + random.nextDouble());
            Ray ray = new Ray(passing.minus(d.times(10)), d);
            assertMiss(String.format(Locale.ROOT, "%s: the ray %s + t·%s passes %.3g from its axis", cylinder, ray.origin, d, distance),
                    cylinder, new IntersectionRecord(), ray);
        }
    }

    @Test
    public void aRecordHoldingAFartherHitDoesNotStopACloserOne() {
        // The record's own t means nothing to intersect; only ray.end bounds the search.
        Cylinder cylinder = new Cylinder(v(0, -1, 0), 2, 2);
        IntersectionRecord out = new IntersectionRecord();
        out.t = 0.5;
        assertHitAt("(0,0,10) toward −z at the side at z = 2, whatever out.t held", cylinder, out, new Ray(v(0, 0, 10), v(0, 0, -1)),
                8, 1e-12);
    }
}
