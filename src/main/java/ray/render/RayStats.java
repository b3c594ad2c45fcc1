package ray.render;

import java.util.LinkedHashMap;
import java.util.Map;
import ray.accel.SearchCounter;

/**
 * How many rays of each kind a render traced, and the work they caused. Each thread counts its own;
 * the totals are summed.
 */
public final class RayStats {
    public long camera;
    public long shadow;
    public long reflection;
    /** Phong specular terms evaluated: one per light per hit of a Phong surface (a glaze's substrate too). */
    public long specular;
    /** Texture lookups: one per hit of a textured shader (a glaze's substrate too), when the scene has a light. */
    public long textureLookups;
    /**
     * Ray–primitive intersection tests, counted as they are made (calls of a sphere's, triangle's or
     * cylinder's {@code intersect}), per kind of ray in {@link SearchCounter} order (camera, shadow,
     * reflection).
     */
    public final long[] intersectionTests = new long[SearchCounter.KINDS];
    /** Bounding boxes tested (BVH nodes visited, and the boxes of placed groups), per kind of ray. */
    public final long[] boxTests = new long[SearchCounter.KINDS];

    /** Takes the search counts of one thread (replacing what was taken from it before). */
    void countedSearches(SearchCounter counter) {
        for (int kind = 0; kind < SearchCounter.KINDS; kind++) {
            intersectionTests[kind] = counter.tests(kind);
            boxTests[kind] = counter.boxes(kind);
        }
    }

    /** Intersection tests of every kind of ray. */
    public long totalIntersectionTests() {
        return sum(intersectionTests);
    }

    /** Box tests of every kind of ray. */
    public long totalBoxTests() {
        return sum(boxTests);
    }

    private static long sum(long[] counts) {
        long total = 0;
        for (long c : counts) {
            total += c;
        }
        return total;
    }

    public void add(RayStats other) {
        camera += other.camera;
        shadow += other.shadow;
        reflection += other.reflection;
        specular += other.specular;
        textureLookups += other.textureLookups;
        for (int kind = 0; kind < SearchCounter.KINDS; kind++) {
            intersectionTests[kind] += other.intersectionTests[kind];
            boxTests[kind] += other.boxTests[kind];
        }
    }

    public long total() {
        return camera + shadow + reflection;
    }

    /** The ray counts by kind, in a fixed order, for printing and JSON. */
    public Map<String, Long> byKind() {
        return byKind(new long[] {camera, shadow, reflection});
    }

    /** Counts per kind of ray (in {@link SearchCounter} order) by the kind's name: camera, shadow, reflection. */
    public Map<String, Long> byKind(long[] counts) {
        Map<String, Long> m = new LinkedHashMap<>();
        m.put("camera", counts[SearchCounter.CAMERA]);
        m.put("shadow", counts[SearchCounter.SHADOW]);
        m.put("reflection", counts[SearchCounter.REFLECTION]);
        return m;
    }
}
