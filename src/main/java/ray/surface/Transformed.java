package ray.surface;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Affine;
import ray.shading.Shader;

/**
 * A surface placed by an affine map M. The ray is taken into the surface's own coordinates by
 * M⁻¹; its direction is not renormalized there, so t means the same in both spaces. Hits come
 * back by M, and normals by (M⁻¹)ᵀ (the inverse transpose keeps them perpendicular under
 * non-uniform scale). The hit's {@link HitGeometry} (for new rays) is made in the surface's
 * coordinates and mapped out the same way.
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
    public boolean intersect(IntersectionRecord out, Ray ray) {
        Ray local = new Ray(toLocal.applyToPoint(ray.origin), toLocal.applyToVector(ray.direction), ray.start, ray.end);
        if (!surface.intersect(out, local)) {
            return false;
        }
        // The geometry for new rays is made where the primitive's own numbers are, and carried out.
        HitGeometry geometry = out.geometry().placedBy(toWorld, toLocal);
        out.location = toWorld.applyToPoint(out.location);
        out.normal = toLocal.applyTransposeToVector(out.normal).normalized();
        out.setGeometry(geometry);
        return true;
    }

    @Override
    public Shader getShader() {
        return surface.getShader();
    }

    @Override
    public void setShader(Shader shader) {
        surface.setShader(shader);
    }

    @Override
    public void inheritShader(Shader inherited) {
        surface.inheritShader(inherited);
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
