package ray.hidden;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static ray.surface.HitAsserts.assertHit;
import static ray.surface.HitAsserts.assertHitAt;
import static ray.surface.HitAsserts.assertMiss;
import static ray.surface.Records.assertUntouched;
import static ray.surface.Records.copyOf;
import static ray.surface.Records.sentinel;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.HitMessages;
import ray.surface.Sphere;
import ray.testing.Points;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden sphere cases: extreme direction lengths, a ray starting on the sphere (as shadow rays do),
 * an off-center hit from inside along a non-unit direction, a record that already holds a closer t,
 * and a tiny sphere far from the origin.
 */
@Points(value = 1, visibility = Visibility.HIDDEN)
public class SphereHiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private final Sphere unit = new Sphere(Vec3.ZERO, 1);

    @Test
    public void veryLongAndVeryShortDirectionsScaleT() {
        // The hit at (0,0,1) is 4 along −z from (0,0,5): t = 4/|d|.
        IntersectionRecord out = new IntersectionRecord();
        assertHitAt("the ray (0,0,5) + t·(0,0,−1e6) at the unit sphere", unit, out, new Ray(v(0, 0, 5), v(0, 0, -1e6)), 4e-6,
                4e-6 * 1e-12);
        assertVec("location", v(0, 0, 1), out.location, 1e-12);
        assertVec("normal", v(0, 0, 1), out.normal, 1e-12);
        assertHitAt("the ray (0,0,5) + t·(0,0,−1e-6) at the unit sphere", unit, out, new Ray(v(0, 0, 5), v(0, 0, -1e-6)), 4e6,
                4e6 * 1e-12);
        assertVec("normal", v(0, 0, 1), out.normal, 1e-12);
    }

    @Test
    public void rayStartingOnTheSphereDoesNotHitItAtTZero() {
        // From (0,0,1) on the sphere: outward the roots are −2 and 0, inward 0 and 2; t = 0 is not in (0, ∞).
        IntersectionRecord out = sentinel(null);
        IntersectionRecord before = copyOf(out);
        assertMiss("the ray from (0,0,1), on the unit sphere, toward +z leaves it: the root t = 0 is not in (0, ∞)", unit, out,
                new Ray(v(0, 0, 1), v(0, 0, 1)));
        assertUntouched(before, out);
        assertHitAt("the ray from (0,0,1), on the unit sphere, toward −z at its far side", unit, out, new Ray(v(0, 0, 1), v(0, 0, -1)),
                2, 1e-14);
        assertVec("location of the far side", v(0, 0, -1), out.location, 1e-14);
        assertVec("normal of the far side (outward)", v(0, 0, -1), out.normal, 1e-14);
    }

    @Test
    public void offCenterHitFromInsideAlongANonUnitDirection() {
        // Center (1,1,1), radius 2; from (1.6,1,1), f = p − c = (0.6,0,0), along d = (0,3,4) (length 5):
        // |f + t·d|² = 0.36 + 25t² = 4, so t = √3.64/5, and the normal is (f + t·d)/2 = (0.3, 1.5t, 2t).
        Sphere sphere = new Sphere(v(1, 1, 1), 2);
        IntersectionRecord out = new IntersectionRecord();
        double t = Math.sqrt(3.64) / 5;
        assertHitAt("the ray from (1.6,1,1), inside the sphere of center (1,1,1), radius 2, along (0,3,4) (t = √3.64/5, the only"
                + " root in (0, ∞))", sphere, out, new Ray(v(1.6, 1, 1), v(0, 3, 4)), t, 1e-14);
        assertVec("location", v(1.6, 1 + 3 * t, 1 + 4 * t), out.location, 1e-14);
        assertVec("normal (outward)", v(0.3, 1.5 * t, 2 * t), out.normal, 1e-14);
        assertSame(sphere, out.surface);
    }

    @Test
    public void hitReplacesARecordThatHoldsACloserT() {
        // Only ray.start and ray.end limit a hit; whatever the record held before does not.
        Sphere other = new Sphere();
        IntersectionRecord out = sentinel(other);
        out.t = 1;
        assertHitAt("the ray from (0,0,5) toward −z at the unit sphere, into a record whose t was 1 (a hit must replace out.t,"
                + " whatever it held: only ray.start and ray.end limit t)", unit, out, new Ray(v(0, 0, 5), v(0, 0, -1)), 4, 1e-14);
        assertSame("a hit must set out.surface", unit, out.surface);
        assertVec("a hit must set out.normal", v(0, 0, 1), out.normal, 1e-14);
    }

    @Test
    public void tinySphereFarFromTheOrigin() {
        // Radius 1e-3 at (1000, −2000, 500), seen from 10 above its center: t = 10 − 1e-3.
        Vec3 center = v(1000, -2000, 500);
        Sphere tiny = new Sphere(center, 1e-3);
        IntersectionRecord out = new IntersectionRecord();
        assertHitAt("the ray from 10 above the center toward −z at the sphere of radius 1e-3 at (1000,−2000,500)", tiny, out,
                new Ray(center.plus(v(0, 0, 10)), v(0, 0, -1)), 10 - 1e-3, 1e-9);
        assertVec("location", v(1000, -2000, 500.001), out.location, 1e-9);
        assertVec("normal", v(0, 0, 1), out.normal, 1e-6);
        IntersectionRecord miss = new IntersectionRecord();
        assertMiss("the ray 2e-3 beside the center of the sphere of radius 1e-3", tiny, miss,
                new Ray(center.plus(v(2e-3, 0, 10)), v(0, 0, -1)));
    }

    /**
     * Seeded: spheres of radius 0.1 to 10 up to 10 from the origin, hit from outside at a point of
     * latitude within ±80° and longitude not within 5° of the seam; the reported (u, v) must give
     * back the point's direction: longitude 2π(u − ½), latitude π(v − ½).
     */
    @Test
    public void textureCoordinatesGiveBackTheHitDirection() {
        java.util.Random random = new java.util.Random(2_000_014);
        for (int k = 0; k < 300; k++) {
            Vec3 center = v(20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10);
            double radius = 0.1 + 9.9 * random.nextDouble();
            double longitude = Math.toRadians(-175 + 350 * random.nextDouble());
            double latitude = Math.toRadians(-80 + 160 * random.nextDouble());
            Vec3 n = v(Math.cos(latitude) * Math.sin(longitude), Math.sin(latitude), Math.cos(latitude) * Math.cos(longitude));
            Vec3 point = center.plus(n.times(radius));
            // Come in along −n scaled by 0.5 to 3, from 1 to 5 radii out.
            Vec3 d = n.times(-(0.5 + 2.5 * random.nextDouble()));
            Vec3 origin = point.minus(d.times(radius * (1 + 4 * random.nextDouble()) / d.length()));
            Sphere sphere = new Sphere(center, radius);
            IntersectionRecord out = new IntersectionRecord();
            String what = sphere + ", the ray " + origin + " + t·" + d + " toward the point at longitude "
                    + Math.toDegrees(longitude) + "°, latitude " + Math.toDegrees(latitude) + "°";
            assertHit(what, sphere, out, new Ray(origin, d));
            String returned = what + ": " + HitMessages.returned(out, false) + " with the normal " + out.normal + "; ";
            assertEquals(returned + "out.texU = ½ + longitude/2π", 0.5 + longitude / (2 * Math.PI), out.texU, 1e-9);
            assertEquals(returned + "out.texV = ½ + latitude/π", 0.5 + latitude / Math.PI, out.texV, 1e-9);
        }
    }
}
