package ray.inspect;

import ray.surface.Surface;

/**
 * Short names of surfaces, with the numbers that tell them apart (center, vertices, bounds, file),
 * as the trace and the explore page show them: each surface describes itself
 * ({@link Surface#describe}), its numbers written as the trace writes them ({@link Fmt#num}).
 */
public final class SurfaceNames {
    public String of(Surface s) {
        return s.describe(Fmt::num);
    }
}
