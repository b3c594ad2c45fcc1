package ray.surface;

import java.util.Set;
import java.util.function.DoubleFunction;
import ray.IntersectionRecord;
import ray.math.Affine;
import ray.math.Bounds;
import ray.math.Vec3;
import ray.shading.Effect;

/** What the framework knows of a triangle ({@link TriangleSurface}) besides its ray test. */
final class TriangleFacts implements ShapeFacts {
    static final TriangleFacts FACTS = new TriangleFacts();

    private TriangleFacts() {
    }

    /** Whether the triangle has vertex normals (a smooth triangle), whose blend is its shading normal. */
    static boolean hasVertexNormals(TriangleSurface t) {
        return t.n0 != null;
    }

    /**
     * Whether an edge cross product (v1 − v0) × (v2 − v0) is a usable normal: finite, and not zero or
     * underflowed to zero. The one test of a triangle's area, for {@link #complete} and
     * {@link TriangleSurface#getFaceNormal}.
     */
    static boolean spansArea(Vec3 cross) {
        return cross.isFinite() && cross.lengthSquared() > 0;
    }

    /** Finds out whether the triangle is degenerate ({@link TriangleSurface#isDegenerate}). */
    @Override
    public Surface complete(Surface s) {
        TriangleSurface t = (TriangleSurface) s;
        t.degenerate = !spansArea(t.v1.minus(t.v0).cross(t.v2.minus(t.v0)));
        return s;
    }

    @Override
    public Set<Effect> effects(Surface s) {
        return hasVertexNormals((TriangleSurface) s) ? Set.of(Effect.VERTEX_NORMALS) : Set.of();
    }

    /** The same triangle, vertex normals and texture coordinates with its vertices moved (normals do not move). */
    @Override
    public Surface inFrameAt(Surface s, Vec3 origin) {
        TriangleSurface t = (TriangleSurface) s;
        TriangleSurface moved = (TriangleSurface) t.shallowCopy();
        moved.v0 = t.v0.minus(origin);
        moved.v1 = t.v1.minus(origin);
        moved.v2 = t.v2.minus(origin);
        return moved.complete();
    }

    /**
     * The hit projected onto the triangle's plane, along the face normal (never the blended one),
     * with a scale that grows with thinness. A thin triangle's normal and a new ray's test of it
     * (edge functions or Cramer's rule, products of edges that nearly cancel) lose precision in
     * proportion to longest edge² / |e1 × e2|, about 1/sin of its smallest angle (1.15 when
     * equilateral); capped at {@link HitGeometry#MAX_THINNESS} (and NaN, for a triangle of no area,
     * replaced) so that even a nearly degenerate triangle's rays start within 1e6·(a few ε) of its
     * coordinates' scale.
     */
    @Override
    public HitGeometry hitGeometry(Surface s, IntersectionRecord hit) {
        TriangleSurface t = (TriangleSurface) s;
        Vec3 v0 = t.v0;
        Vec3 p = hit.location;
        Vec3 n = t.getFaceNormal();
        Vec3 e1 = t.v1.minus(v0);
        Vec3 e2 = t.v2.minus(v0);
        double coordinates = Math.max(Math.max(v0.maxAbs(), t.v1.maxAbs()), Math.max(t.v2.maxAbs(), p.maxAbs()));
        double longest = Math.max(Math.max(e1.lengthSquared(), e2.lengthSquared()), e2.minus(e1).lengthSquared());
        double thinness = longest / e1.cross(e2).length();
        thinness = thinness <= HitGeometry.MAX_THINNESS ? thinness : HitGeometry.MAX_THINNESS;
        // p − ((p − v0)·n) n: the hit on the triangle's plane, wherever the ray that found it came from.
        Vec3 point = p.plusScaled(-p.minus(v0).dot(n), n);
        // Off the plane by: |p − v0| times the normal's angle error, γ(6)·thinness (edges rounded, a
        // cross product of nearly parallel edges, a normalization), plus γ(4)·|p − v0| for the dot
        // product, along n; and one rounding of each coordinate of the result.
        double offPlane = p.minus(v0).length() * (HitGeometry.gamma(6) * thinness + HitGeometry.gamma(4));
        double rounding = HitGeometry.gamma(2);
        Vec3 error = new Vec3(offPlane * Math.abs(n.x) + rounding * Math.abs(point.x),
                offPlane * Math.abs(n.y) + rounding * Math.abs(point.y),
                offPlane * Math.abs(n.z) + rounding * Math.abs(point.z));
        return new HitGeometry(p, point, n, coordinates * thinness, error);
    }

    @Override
    public Bounds bounds(Surface s) {
        TriangleSurface t = (TriangleSurface) s;
        return Bounds.of(t.v0, t.v1, t.v2);
    }

    @Override
    public String name(Surface s) {
        TriangleSurface t = (TriangleSurface) s;
        return "Triangle[" + t.v0 + ", " + t.v1 + ", " + t.v2 + "]";
    }

    @Override
    public SurfaceKind kind() {
        return SurfaceKind.TRIANGLE;
    }

    @Override
    public String describe(Surface s, DoubleFunction<String> number) {
        TriangleSurface t = (TriangleSurface) s;
        return "Triangle " + ShapeFacts.vec(t.v0, number) + ", " + ShapeFacts.vec(t.v1, number) + ", " + ShapeFacts.vec(t.v2, number);
    }

    /** Any placement maps a triangle to a triangle. */
    @Override
    public void sketch(Surface s, Sketch sketch, Affine toWorld) {
        TriangleSurface t = (TriangleSurface) s;
        sketch.triangle(toWorld.applyToPoint(t.v0), toWorld.applyToPoint(t.v1), toWorld.applyToPoint(t.v2));
    }
}
