package ray.surface;

import ray.IntersectionRecord;

/**
 * The one wording of an intersection failure, so that every surface test says the same two things
 * the same way: what the test expected, and what the student's intersect returned, e.g.
 * "…: expected a hit at t = 3 (β = 0.25, γ = 0.25); your intersect returned t = 3.5 (β = 0.5, γ = 0.25)".
 * A student can only find a bug from the numbers their own code produced, so a message without them
 * is a guess. β and γ shown for a returned hit are the record's own out.beta and out.gamma.
 */
public final class HitMessages {
    private HitMessages() {
    }

    /** "a hit at t = 4". */
    public static String hitAt(double t) {
        return "a hit at t = " + number(t);
    }

    /** "a hit at t = 3 (β = 0.25, γ = 0.5)". */
    public static String hitAt(double t, double beta, double gamma) {
        return hitAt(t) + " (" + barycentrics(beta, gamma) + ")";
    }

    /** "a hit with β = 0.25, γ = 0.5", for a check of the barycentrics alone. */
    public static String hitWith(double beta, double gamma) {
        return "a hit with " + barycentrics(beta, gamma);
    }

    /** What an intersect that reported a miss returned. */
    public static String returnedFalse() {
        return "your intersect returned false";
    }

    /** "your intersect returned t = 3.5", with " (β = …, γ = …)" from the record when {@code barycentrics}. */
    public static String returned(IntersectionRecord out, boolean barycentrics) {
        return "your intersect returned " + values(out, barycentrics);
    }

    /** What an intersect that should have missed returned: "your intersect returned true with t = …". */
    public static String returnedTrue(IntersectionRecord out, boolean barycentrics) {
        return "your intersect returned true with " + values(out, barycentrics);
    }

    /**
     * "what: expected E; R", then "; hint" when the numbers name a likely cause (hint may be null) and
     * the task's hint level shows causes ({@link ray.testing.Hints}: not at goal).
     */
    public static String line(String what, String expected, String returned, String hint) {
        return what + ": expected " + expected + "; " + returned + (hint == null || !ray.testing.Hints.fixesShown() ? "" : "; " + hint);
    }

    private static String values(IntersectionRecord out, boolean barycentrics) {
        return "t = " + number(out.t) + (barycentrics ? " (" + barycentrics(out.beta, out.gamma) + ")" : "");
    }

    private static String barycentrics(double beta, double gamma) {
        return "β = " + number(beta) + ", γ = " + number(gamma);
    }

    /**
     * A double as a student would write it: whole numbers without ".0" ("3", not "3.0"), anything
     * else exactly as Java prints it, which is the shortest text that reads back as the same double,
     * so no digit that tells two results apart is lost; infinity as the tests write it, "∞".
     */
    public static String number(double x) {
        if (Double.isInfinite(x)) {
            return x > 0 ? "∞" : "-∞";
        }
        if (x == Math.rint(x) && Math.abs(x) < 1e15) {
            return Long.toString((long) x);
        }
        return Double.toString(x);
    }
}
