package ray.grading.wire;

import ray.IntersectionRecord;
import ray.math.Vec3;

/**
 * Records and rays compared as a question's key: numbers by their exact bits, vectors by their
 * coordinates, the surface by identity. Two questions with equal keys get the same answer from code
 * that answers by its inputs alone, which is the contract.
 */
public final class RecordValues {
    private RecordValues() {
    }

    public static boolean same(double a, double b) {
        return Double.doubleToRawLongBits(a) == Double.doubleToRawLongBits(b);
    }

    public static boolean same(Vec3 a, Vec3 b) {
        return a == null ? b == null : b != null && same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
    }

    public static boolean equal(IntersectionRecord a, IntersectionRecord b) {
        return same(a.t, b.t) && same(a.location, b.location) && same(a.normal, b.normal) && a.surface == b.surface
                && same(a.beta, b.beta) && same(a.gamma, b.gamma) && same(a.texU, b.texU) && same(a.texV, b.texV);
    }

    public static int hash(IntersectionRecord r) {
        long h = Double.doubleToRawLongBits(r.t);
        h = h * 31 + hash(r.location);
        h = h * 31 + hash(r.normal);
        h = h * 31 + System.identityHashCode(r.surface);
        h = h * 31 + Double.doubleToRawLongBits(r.beta);
        h = h * 31 + Double.doubleToRawLongBits(r.gamma);
        h = h * 31 + Double.doubleToRawLongBits(r.texU);
        h = h * 31 + Double.doubleToRawLongBits(r.texV);
        return Long.hashCode(h);
    }

    private static long hash(Vec3 v) {
        return v == null ? 7 : (Double.doubleToRawLongBits(v.x) * 31 + Double.doubleToRawLongBits(v.y)) * 31 + Double.doubleToRawLongBits(v.z);
    }
}
