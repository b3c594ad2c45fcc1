package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static ray.testing.Asserts.v;

import ray.IntersectionRecord;

/** Sentinel intersection records for the surface tests: a miss must leave every field as it was. */
final class Records {
    private Records() {
    }

    /** A record holding recognizable values (t = 123, location (7,7,7), β = 0.25, γ = 0.5). */
    static IntersectionRecord sentinel(Surface surface) {
        IntersectionRecord out = new IntersectionRecord();
        out.t = 123;
        out.location = v(7, 7, 7);
        out.normal = v(0, 1, 0);
        out.surface = surface;
        out.beta = 0.25;
        out.gamma = 0.5;
        return out;
    }

    /** Every field of {@code actual} is the very value {@code expected} holds. */
    static void assertUntouched(IntersectionRecord expected, IntersectionRecord actual) {
        assertEquals("t", expected.t, actual.t, 0);
        assertSame("location", expected.location, actual.location);
        assertSame("normal", expected.normal, actual.normal);
        assertSame("surface", expected.surface, actual.surface);
        assertEquals("beta", expected.beta, actual.beta, 0);
        assertEquals("gamma", expected.gamma, actual.gamma, 0);
    }

    static IntersectionRecord copyOf(IntersectionRecord record) {
        IntersectionRecord copy = new IntersectionRecord();
        copy.set(record);
        return copy;
    }
}
