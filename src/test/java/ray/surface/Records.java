package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static ray.testing.Asserts.v;

import ray.IntersectionRecord;

/** Sentinel intersection records for the surface tests: a miss must leave every field as it was. */
public final class Records {
    private Records() {
    }

    /** A record holding recognizable values (t = 123, location (7,7,7), β = 0.25, γ = 0.5, texture coordinates (0.125, 0.375)). */
    public static IntersectionRecord sentinel(Surface surface) {
        IntersectionRecord out = new IntersectionRecord();
        out.t = 123;
        out.location = v(7, 7, 7);
        out.normal = v(0, 1, 0);
        out.surface = surface;
        out.beta = 0.25;
        out.gamma = 0.5;
        out.texU = 0.125;
        out.texV = 0.375;
        return out;
    }

    /** Every field of {@code actual} is the very value {@code expected} holds. */
    public static void assertUntouched(IntersectionRecord expected, IntersectionRecord actual) {
        String rule = "a miss must leave the record exactly as it was, but it changed ";
        assertEquals(rule + "out.t", expected.t, actual.t, 0);
        assertSame(rule + "out.location", expected.location, actual.location);
        assertSame(rule + "out.normal", expected.normal, actual.normal);
        assertSame(rule + "out.surface", expected.surface, actual.surface);
        assertEquals(rule + "out.beta", expected.beta, actual.beta, 0);
        assertEquals(rule + "out.gamma", expected.gamma, actual.gamma, 0);
        assertEquals(rule + "out.texU", expected.texU, actual.texU, 0);
        assertEquals(rule + "out.texV", expected.texV, actual.texV, 0);
    }

    public static IntersectionRecord copyOf(IntersectionRecord record) {
        IntersectionRecord copy = new IntersectionRecord();
        copy.set(record);
        return copy;
    }
}
