package ray.render;

import java.util.LinkedHashMap;
import java.util.Map;

/** How many rays of each kind a render traced. Each thread counts its own; the totals are summed. */
public final class RayStats {
    public long camera;
    public long shadow;
    public long reflection;

    public void add(RayStats other) {
        camera += other.camera;
        shadow += other.shadow;
        reflection += other.reflection;
    }

    public long total() {
        return camera + shadow + reflection;
    }

    /** The counts by kind, in a fixed order, for printing and JSON. */
    public Map<String, Long> byKind() {
        Map<String, Long> m = new LinkedHashMap<>();
        m.put("camera", camera);
        m.put("shadow", shadow);
        m.put("reflection", reflection);
        return m;
    }
}
