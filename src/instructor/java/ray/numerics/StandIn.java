package ray.numerics;

import ray.IntersectionRecord;
import ray.Ray;
import ray.shading.Shader;
import ray.surface.HitGeometry;
import ray.surface.Surface;

/**
 * A primitive tested by another method (textbook formulas, float arithmetic) standing in for the
 * scene's own: it shades with the original's shader and measures its hits with the original's
 * {@link Surface#hitGeometry}, so only the intersection test differs. Its hits name the stand-in,
 * which is where it sits in the rendered tree (the framework finds a hit's transforms by it).
 */
abstract class StandIn extends Surface {
    private final Surface original;

    StandIn(Surface original) {
        this.original = original;
    }

    /** The stand-in's test: fills out (t, location, normal, barycentrics) on a hit, as intersect does. */
    protected abstract boolean test(IntersectionRecord out, Ray ray);

    @Override
    public final boolean intersect(IntersectionRecord out, Ray ray) {
        if (!test(out, ray)) {
            return false;
        }
        out.surface = this;
        return true;
    }

    @Override
    public Shader getShader() {
        return original.getShader();
    }

    @Override
    public HitGeometry hitGeometry(IntersectionRecord hit) {
        return original.hitGeometry(hit);
    }

    @Override
    public String toString() {
        return original.toString();
    }
}
