package ray.surface;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import ray.IntersectionRecord;
import ray.math.Affine;
import ray.math.Vec3;

/**
 * Where each primitive of a surface tree sits: the transforms between the root and it. The renderer
 * asks for a hit's {@link HitGeometry} after the closest hit is found, with the hit as the root
 * reports it; the geometry is made where the primitive's own numbers are, so the hit is taken back
 * into the primitive's coordinates (location by M⁻¹, normal by Mᵀ), measured there by the
 * primitive's {@link Surface#hitGeometry} and taken out again (point by M, normal by (M⁻¹)ᵀ, scale
 * by {@link Affine#pointScale}). A
 * primitive reached by several paths (a named group reused) takes the path whose re-projected point
 * lies nearest the hit.
 */
public final class Placements {
    /** One transform on a path: the map out of it and its inverse. */
    private static final class Level {
        final Affine toWorld;
        final Affine toLocal;

        Level(Affine toWorld) {
            this.toWorld = toWorld;
            this.toLocal = toWorld.inverse();
        }
    }

    /** The primitives under at least one transform, each with its paths (outermost transform first). */
    private final Map<Surface, List<List<Level>>> paths = new IdentityHashMap<>();

    private Placements() {
    }

    /** The placements of every primitive under {@code root}. */
    public static Placements of(Surface root) {
        Placements placements = new Placements();
        placements.walk(root, List.of());
        return placements;
    }

    private void walk(Surface surface, List<Level> above) {
        List<Level> here = above;
        Affine placement = surface.childPlacement();
        if (!placement.isIdentity()) {
            List<Level> longer = new ArrayList<>(above);
            longer.add(new Level(placement));
            here = List.copyOf(longer);
        }
        List<Surface> children = surface.children();
        if (children.isEmpty()) {
            if (!here.isEmpty()) {
                paths.computeIfAbsent(surface, s -> new ArrayList<>(1)).add(here);
            }
            return;
        }
        for (Surface child : children) {
            walk(child, here);
        }
    }

    /** The geometry of {@code hit}, a hit that the root reported (in the root's coordinates). */
    public HitGeometry geometryOf(IntersectionRecord hit) {
        if (hit.surface == null) {
            return HitGeometry.atReportedPoint(hit);
        }
        List<List<Level>> found = paths.get(hit.surface);
        if (found == null) {
            return hit.surface.hitGeometry(hit);
        }
        HitGeometry best = null;
        double bestDistance = Double.POSITIVE_INFINITY;
        for (List<Level> path : found) {
            HitGeometry g = alongPath(hit, path);
            double distance = g.point.minus(hit.location).lengthSquared();
            if (best == null || distance < bestDistance) {
                best = g;
                bestDistance = distance;
            }
        }
        return best;
    }

    private static HitGeometry alongPath(IntersectionRecord hit, List<Level> path) {
        IntersectionRecord local = new IntersectionRecord();
        local.set(hit);
        for (Level level : path) {
            local.location = level.toLocal.applyToPoint(local.location);
            // A normal goes out by (M⁻¹)ᵀ, so back in by Mᵀ.
            local.normal = local.normal == null ? null : level.toWorld.applyTransposeToVector(local.normal).normalized();
        }
        HitGeometry g = hit.surface.hitGeometry(local);
        Vec3 point = g.point;
        Vec3 normal = g.normal;
        double scale = g.scale;
        Vec3 error = g.error;
        for (int i = path.size() - 1; i >= 0; i--) {
            Level level = path.get(i);
            error = level.toWorld.pointError(point, error);
            point = level.toWorld.applyToPoint(point);
            // A new ray from here is mapped back in before its test, which rounds its origin again:
            // that error, seen from out here, is |M| times the inverse map's own rounding.
            error = error.plus(level.toWorld.linearBound(level.toLocal.pointError(point, Vec3.ZERO)).times(1 + HitGeometry.gamma(3)));
            normal = level.toLocal.applyTransposeToVector(normal).normalized();
            scale = level.toWorld.pointScale(scale);
        }
        return new HitGeometry(hit.location, point, normal, scale, error);
    }
}
