package ray.grading.judge;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import ray.IntersectionRecord;
import ray.grading.wire.RecordValues;

/**
 * The questions guessed during a round, gathered for the next batch: intersects by ray (each ray's
 * candidates and the stand-ins asked), and camera and texture calls. The render's threads add to it
 * at once; the round's end takes it whole.
 */
final class Questions {
    final Map<RayKey, PerRay> intersects = new ConcurrentHashMap<>();
    final Map<UvKey, StandIn> cameraCalls = new ConcurrentHashMap<>();
    final Map<UvKey, StandIn> textureCalls = new ConcurrentHashMap<>();

    /** One ray's guessed intersects: its candidates (end and record before) and the stand-ins asked, each once. */
    static final class PerRay {
        final List<Double> ends = new ArrayList<>(2);
        final List<IntersectionRecord> befores = new ArrayList<>(2);
        final List<StandIn> targets = new ArrayList<>(2);

        synchronized void add(StandIn target, double end, IntersectionRecord before) {
            boolean known = false;
            for (StandIn t : targets) {
                known |= t == target;
            }
            if (!known) {
                targets.add(target);
            }
            for (int c = 0; c < ends.size(); c++) {
                if (RecordValues.same(ends.get(c), end) && RecordValues.equal(befores.get(c), before)) {
                    return;
                }
            }
            IntersectionRecord copy = new IntersectionRecord();
            copy.set(before);
            ends.add(end);
            befores.add(copy);
        }
    }

    void intersect(StandIn target, RayKey key, double end, IntersectionRecord before) {
        intersects.computeIfAbsent(key, k -> new PerRay()).add(target, end, before);
    }

    boolean isEmpty() {
        return intersects.isEmpty() && cameraCalls.isEmpty() && textureCalls.isEmpty();
    }

    /** A camera's or texture's call: the stand-in and (u, v) by their bits. */
    static final class UvKey {
        final Object target;
        final long u;
        final long v;

        UvKey(Object target, double u, double v) {
            this.target = target;
            this.u = Double.doubleToRawLongBits(u);
            this.v = Double.doubleToRawLongBits(v);
        }

        double uValue() {
            return Double.longBitsToDouble(u);
        }

        double vValue() {
            return Double.longBitsToDouble(v);
        }

        @Override
        public int hashCode() {
            return System.identityHashCode(target) * 31 + Long.hashCode(u * 0x9E3779B97F4A7C15L + v);
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof UvKey && ((UvKey) o).target == target && ((UvKey) o).u == u && ((UvKey) o).v == v;
        }
    }
}
