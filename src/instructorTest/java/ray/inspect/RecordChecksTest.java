package ray.inspect;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.camera.PerspectiveCamera;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.surface.SphereSurface;
import ray.surface.Surface;

/**
 * {@code ray1 trace} checks what a hit record claims: a t outside the ray's segment (a surface that
 * ignores ray.start, whose blocker behind a shadow ray's start darkens a lit point) and a normal
 * that is not unit length (a sphere that assumes |d| = 1). Both were the real causes behind a
 * student's wrong sphere render that the trace showed without saying so.
 */
public class RecordChecksTest {
    /** Reports a hit at t = −2 on any ray heading toward +z (a shadow ray here), ignoring the segment; misses the rest. */
    private static final class IgnoresStart extends Surface {
        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            if (ray.direction.z <= 0) {
                return false;
            }
            out.t = -2;
            out.location = ray.pointAt(-2);
            out.normal = v(0, 0, 1);
            out.surface = this;
            return true;
        }

        @Override
        public String toString() {
            return "IgnoresStart";
        }
    }

    @Test
    public void tInsideTheSegmentPassesAndOutsideIsNamedBySide() {
        Ray ray = new Ray(v(0, 0, 0), v(0, 0, 1), 0, 10);
        assertNull(RecordChecks.outsideSegment(4, ray, "camera ray"));
        String behind = RecordChecks.outsideSegment(-9.5, ray, "shadow ray");
        assertEquals("t = " + Fmt.num(-9.5) + " lies behind the shadow ray's start (0): a hit must lie in (start, end);"
                + " does that intersect check ray.start?", behind);
        assertTrue(RecordChecks.outsideSegment(0, ray, "camera ray").contains("behind the camera ray's start"));
        assertTrue(RecordChecks.outsideSegment(10, ray, "camera ray").contains("beyond the camera ray's end (10)"));
        assertTrue(RecordChecks.outsideSegment(Double.NaN, ray, "camera ray").startsWith("t is NaN"));
    }

    @Test
    public void aNormalIsUnitWithinRoundingAndOtherwiseNamedWithItsLength() {
        assertNull(RecordChecks.notUnit(v(0, 0.6, 0.8)));
        assertNull(RecordChecks.notUnit(v(1 + 1e-9, 0, 0)));
        assertNull(RecordChecks.notUnit(null));
        String longer = RecordChecks.notUnit(v(0, 0, 2.4691));
        assertTrue(longer, longer.startsWith("the normal is not unit length: |n| = 2.4691;"));
    }

    @Test
    public void everyFailingCheckOfAHitIsListedInTheTracesOrder() {
        IntersectionRecord hit = new IntersectionRecord();
        hit.t = -3;
        hit.normal = v(0, 0, 2);
        hit.location = v(0, 0, 8);
        java.util.List<String> flags = RecordChecks.of(hit, new Ray(v(0, 0, 5), v(0, 0, -1)));
        assertEquals(flags.toString(), 2, flags.size());
        assertTrue(flags.get(0), flags.get(0).startsWith("t = " + Fmt.num(-3) + " lies behind the camera ray's start"));
        assertTrue(flags.get(1), flags.get(1).startsWith("the normal is not unit length: |n| = 2;"));
    }

    @Test
    public void theTraceFlagsANormalThatIsNotUnitLength() {
        String out = trace(new Wall(v(0, 0, 2.5)), null);
        assertTrue(out, out.contains("!            the normal is not unit length: |n| = 2.5;"));
        assertTrue(out, out.contains("(the hit's normal, NOT unit length: |n| = 2.5)"));
        assertFalse(out, out.contains("(the hit's unit normal)"));
    }

    @Test
    public void theTraceFlagsAShadowBlockerBehindTheShadowRaysStart() {
        String out = trace(new Wall(v(0, 0, 1)), new IgnoresStart());
        assertTrue(out, out.contains("BLOCKED by #2 IgnoresStart at t = " + Fmt.num(-2)));
        assertTrue(out, out.contains("!            t = " + Fmt.num(-2) + " lies behind the shadow ray's start (0)"));
        assertTrue(out, out.contains("does that intersect check ray.start?"));
        assertTrue(out, out.contains("adds         nothing: the shadow ray is blocked"));
        // The camera ray's hit is the wall's, inside its segment, with a unit normal: nothing flagged there.
        assertFalse(out, out.contains("camera ray's start"));
        assertFalse(out, out.contains("not unit length"));
    }

    /** The explore page's story of the same pixel carries the same checks. */
    @Test
    public void theExploreStoryCarriesTheSameChecks() {
        com.google.gson.JsonObject shadowed = new PixelStory(scene(new Wall(v(0, 0, 1)), new IgnoresStart()), "walls.xml").of(0, 0, null, null);
        com.google.gson.JsonObject blocker = shadowed.getAsJsonArray("lights").get(0).getAsJsonObject().getAsJsonObject("blocker");
        assertTrue(blocker.toString(), blocker.get("check").getAsString().contains("lies behind the shadow ray's start"));
        assertEquals(0, shadowed.getAsJsonObject("closest").getAsJsonArray("recordChecks").size());
        com.google.gson.JsonObject scaled = new PixelStory(scene(new Wall(v(0, 0, 2.5)), null), "walls.xml").of(0, 0, null, null);
        com.google.gson.JsonArray checks = scaled.getAsJsonObject("closest").getAsJsonArray("recordChecks");
        assertEquals(checks.toString(), 1, checks.size());
        assertTrue(checks.toString(), checks.get(0).getAsString().startsWith("the normal is not unit length: |n| = 2.5;"));
    }

    @Test
    public void theTraceFlagsAClosestHitBehindTheCameraRaysStart() {
        // A wall that reports the ray's t = −1 point (behind the eye) on any ray, ignoring the segment.
        Surface behind = new Surface() {
            @Override
            public boolean intersect(IntersectionRecord out, Ray ray) {
                out.t = -1;
                out.location = ray.pointAt(-1);
                out.normal = v(0, 0, 1);
                out.surface = this;
                return true;
            }

            @Override
            public String toString() {
                return "Behind";
            }
        };
        String out = trace(behind, null);
        assertTrue(out, out.contains("!            t = " + Fmt.num(-1) + " lies behind the camera ray's start (0)"));
    }

    /** A sphere that reports the larger root of the quadratic, where the ray leaves it; or the smaller, as it should. */
    private static final class RootSphere extends SphereSurface {
        private final boolean far;

        RootSphere(boolean far) {
            this.far = far;
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            Vec3 oc = ray.origin.minus(center);
            double a = ray.direction.dot(ray.direction);
            double b = 2 * oc.dot(ray.direction);
            double c = oc.dot(oc) - radius * radius;
            double disc = b * b - 4 * a * c;
            if (disc < 0) {
                return false;
            }
            double t = (-b + (far ? 1 : -1) * Math.sqrt(disc)) / (2 * a);
            if (!(ray.start < t && t < ray.end)) {
                return false;
            }
            out.t = t;
            out.location = ray.pointAt(t);
            out.normal = out.location.minus(center).times(1 / radius);
            out.surface = this;
            return true;
        }

        @Override
        public String toString() {
            return "RootSphere";
        }
    }

    /** From (0, 0, 5) the unit sphere's roots are t = 4 (entering at z = 1) and t = 6 (leaving at z = −1, normal (0, 0, −1)). */
    @Test
    public void theTraceFlagsASphereHitAtItsFarRootFromOutside() {
        String far = trace(new RootSphere(true), null);
        assertTrue(far, far.contains("t            6"));
        assertTrue(far, far.contains("!            the ray starts outside the sphere, yet this normal faces away from the eye (n·d > 0)"));
        assertTrue(far, far.contains("is this the far root?"));
        String near = trace(new RootSphere(false), null);
        assertTrue(near, near.contains("t            4"));
        assertFalse(near, near.contains("far root"));
    }

    /** The trace of the one pixel of {@link #scene}. */
    private static String trace(Surface wall, Surface other) {
        StringWriter text = new StringWriter();
        try (PrintWriter out = new PrintWriter(text)) {
            new PixelTrace(scene(wall, other), "walls.xml", false, 0).run(0, 0, out);
        }
        return text.toString();
    }

    /** A 1×1 view of {@code wall} (and {@code other}) from (0, 0, 5), lit from (0, 0, 10). */
    private static Scene scene(Surface wall, Surface other) {
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewPoint(v(0, 0, 5));
        camera.complete();
        Scene scene = new Scene();
        scene.setCamera(camera);
        scene.setImage(1, 1);
        Lambertian gray = new Lambertian(v(0.5, 0.5, 0.5));
        scene.addShader(gray);
        wall.setShader(gray);
        scene.addSurface(wall);
        if (other != null) {
            other.setShader(gray);
            scene.addSurface(other);
        }
        scene.addLight(new Light(v(0, 0, 10), v(1, 1, 1)));
        scene.complete();
        return scene;
    }
}
