package ray.shading;

import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.testing.Hints;

/**
 * A shading case for the light loops, built by hand: one hit (its point, unit normal and the ray
 * that found it), the scene's lights, and which of them something blocks. Its context answers the
 * shadow tests from that list and notes them, so a test can say which light a shadow test asked
 * about. A mirror ray is an error unless the case says what the mirror direction brings back
 * ({@link #mirrorSees}); then each mirror ray's direction and depth are noted.
 */
final class LitPoint {
    final IntersectionRecord hit = new IntersectionRecord();
    final Ray ray;
    private final List<Light> lights = new ArrayList<>();
    private final Set<Vec3> blocked = new HashSet<>();
    /** The light positions the shader's shadow tests asked about, in order. */
    final List<Vec3> asked = new ArrayList<>();
    /** What the shader asked of the context that the contract rules out, or null (checked once shade returns, so no student code catches it). */
    private String misuse;
    /** What a mirror ray brings back, or null when the shader must trace none. */
    private Vec3 mirrorColor;
    /** The directions and depths of the mirror rays the shader asked for, in order. */
    final List<Vec3> mirrorDirections = new ArrayList<>();
    final List<Integer> mirrorDepths = new ArrayList<>();

    /** The point {@code location} with unit normal {@code normal}, seen from {@code eye}. */
    LitPoint(Vec3 location, Vec3 normal, Vec3 eye) {
        hit.location = location;
        hit.normal = normal;
        Vec3 d = location.minus(eye);
        hit.t = 1;
        ray = new Ray(eye, d);
    }

    LitPoint light(Vec3 position, Vec3 intensity) {
        lights.add(new Light(position, intensity));
        return this;
    }

    /** Mirror rays are expected, and each brings back {@code color}. */
    LitPoint mirrorSees(Vec3 color) {
        mirrorColor = color;
        return this;
    }

    /** A light that something blocks: its shadow test says so. */
    LitPoint blockedLight(Vec3 position, Vec3 intensity) {
        light(position, intensity);
        blocked.add(position);
        return this;
    }

    final ShadingContext context = new ShadingContext() {
        @Override
        public List<Light> lights() {
            return java.util.Collections.unmodifiableList(lights);
        }

        @Override
        public boolean unoccluded(IntersectionRecord at, Vec3 lightPosition) {
            boolean known = false;
            for (Light l : lights) {
                known |= l.getPosition().equals(lightPosition);
            }
            if (at != hit && misuse == null) {
                misuse = "the shadow test was asked about another hit than the one being shaded" + Hints.fix("; pass it the hit shade was given");
            } else if (!known && misuse == null) {
                misuse = "the shadow test was asked about " + lightPosition + ", which is no light's position (the lights are at "
                        + positions() + ")" + Hints.fix("; pass it light.getPosition()");
            }
            asked.add(lightPosition);
            return !blocked.contains(lightPosition);
        }

        @Override
        public Vec3 radiance(IntersectionRecord at, Vec3 direction, int depth) {
            if (mirrorColor == null) {
                if (misuse == null) {
                    misuse = "this shader has no mirror term (a Lambertian or Phong, or a mirror coefficient of zero), but"
                            + " context.radiance was called";
                }
                return Vec3.ZERO;
            }
            if (at != hit && misuse == null) {
                misuse = "the mirror ray was asked from another hit than the one being shaded" + Hints.fix("; pass it the hit shade was given");
            }
            mirrorDirections.add(direction);
            mirrorDepths.add(depth);
            return mirrorColor;
        }
    };

    private List<Vec3> positions() {
        List<Vec3> p = new ArrayList<>();
        for (Light l : lights) {
            p.add(l.getPosition());
        }
        return p;
    }

    /** What {@code shader} returns here, for a camera ray. */
    Vec3 shade(Shader shader) {
        return shade(shader, 0);
    }

    /** What {@code shader} returns here, for a ray of recursion depth {@code depth}. */
    Vec3 shade(Shader shader, int depth) {
        Vec3 result = shader.shade(hit, ray, context, depth);
        if (misuse != null) {
            fail("shading " + describe() + ": " + misuse);
        }
        return result;
    }

    /**
     * Checks that {@code shader} returns {@code expected} here, each channel within a billionth of
     * it (the lights may be summed in any order, the terms multiplied in any grouping).
     *
     * @param why the expected value worked out, shown where the hint level shows formulas
     */
    void check(Shader shader, Vec3 expected, String why) {
        Vec3 result = shade(shader);
        String message = shader.getClass().getSimpleName() + ".shade at " + describe() + " returned " + result + "; expected " + expected
                + Hints.fix(why.isEmpty() ? "" : " (" + why + ")");
        assertTrue(message, result != null);
        for (int axis = 0; axis < 3; axis++) {
            double e = expected.get(axis);
            assertTrue(message, Math.abs(result.get(axis) - e) <= 1e-9 * Math.max(1, Math.abs(e)));
        }
    }

    /** The case in words, for messages: "the point (0, 0, 0) with normal (0, 0, 1) seen from (0, 0, 2), lit by …". */
    String describe() {
        StringBuilder s = new StringBuilder("the point " + hit.location + " with normal " + hit.normal + " seen from " + ray.origin);
        if (lights.isEmpty()) {
            return s.append(" with no lights").toString();
        }
        s.append(", lit by");
        for (int k = 0; k < lights.size(); k++) {
            Light l = lights.get(k);
            s.append(k == 0 ? " " : "; ").append("a light at ").append(l.getPosition()).append(" of intensity ").append(l.getIntensity());
            if (blocked.contains(l.getPosition())) {
                s.append(" (blocked)");
            }
        }
        return s.toString();
    }
}
