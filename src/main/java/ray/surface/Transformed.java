package ray.surface;

import java.util.List;
import java.util.Set;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Affine;
import ray.shading.Effect;
import ray.shading.Shader;

/**
 * A surface placed by an affine map M (see {@link Placement}). The ray is taken into the surface's
 * own coordinates by M⁻¹; its direction is not renormalized there, so t means the same in both
 * spaces. A hit's location comes back by M and its normal by (M⁻¹)ᵀ (the inverse transpose keeps
 * normals perpendicular under non-uniform scale); its other fields are the same in both spaces.
 */
public final class Transformed extends Surface {
    private final Surface surface;
    private final Affine toWorld;
    private final Affine toLocal;

    public Transformed(Surface surface, Affine toWorld) {
        this.surface = surface;
        this.toWorld = toWorld;
        this.toLocal = toWorld.inverse();
    }

    public Affine toWorld() {
        return toWorld;
    }

    @Override
    public Affine childPlacement() {
        return toWorld;
    }

    @Override
    public Set<Effect> effects() {
        return Set.of(Effect.TRANSFORMS);
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        Ray local = new Ray(toLocal.applyToPoint(ray.origin), toLocal.applyToVector(ray.direction), ray.start, ray.end);
        if (!surface.intersect(out, local)) {
            return false;
        }
        out.location = toWorld.applyToPoint(out.location);
        out.normal = toLocal.applyTransposeToVector(out.normal).normalized();
        return true;
    }

    /** The placed surface's shader: a transform is not a surface of its own. */
    @Override
    public Shader getShader() {
        return surface.getShader();
    }

    @Override
    public void setShader(Shader shader) {
        surface.setShader(shader);
    }

    @Override
    public List<Surface> children() {
        return List.of(surface);
    }

    @Override
    public String toString() {
        return "Transformed[" + toWorld + "]";
    }
}
