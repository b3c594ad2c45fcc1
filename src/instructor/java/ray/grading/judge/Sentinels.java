package ray.grading.judge;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Surface;

/**
 * A record whose every field holds a value no intersect computes (NaNs with a payload arithmetic
 * never makes, vectors and a surface of their own), so that an answer given on it shows exactly
 * which fields the call wrote, whatever values it wrote.
 */
final class Sentinels {
    private static final double MARK = Double.longBitsToDouble(0x7ff4_0000_0bad_cafeL);
    private static final Surface NOBODY = new Surface() {
        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            return false;
        }
    };

    private Sentinels() {
    }

    static IntersectionRecord record() {
        IntersectionRecord r = new IntersectionRecord();
        r.t = MARK;
        r.location = new Vec3(MARK, MARK, MARK);
        r.normal = new Vec3(MARK, MARK, MARK);
        r.surface = NOBODY;
        r.beta = MARK;
        r.gamma = MARK;
        r.texU = MARK;
        r.texV = MARK;
        return r;
    }
}
