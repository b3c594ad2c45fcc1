package ray.render;

import java.util.LinkedHashMap;
import java.util.Map;

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
     * Ray–primitive intersection tests: (rays traced) × (primitives in the scene tree), summed over
     * the ray kinds. Exact for the linear closest-hit loop of Group, which tests every ray against
     * every primitive; a loop that skipped primitives (a bounding volume hierarchy) would need a
     * real counter instead.
     */
    public long intersectionTests;

    public void add(RayStats other) {
        camera += other.camera;
        shadow += other.shadow;
        reflection += other.reflection;
        specular += other.specular;
        textureLookups += other.textureLookups;
        intersectionTests += other.intersectionTests;
    }

    public long total() {
        return camera + shadow + reflection;
    }

    /** The ray counts by kind, in a fixed order, for printing and JSON. */
    public Map<String, Long> byKind() {
        Map<String, Long> m = new LinkedHashMap<>();
        m.put("camera", camera);
        m.put("shadow", shadow);
        m.put("reflection", reflection);
        return m;
    }
}
