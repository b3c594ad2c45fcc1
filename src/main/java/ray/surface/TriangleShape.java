package ray.surface;

import java.util.Set;
import java.util.function.DoubleFunction;
import ray.IntersectionRecord;
import ray.math.Affine;
import ray.math.Bounds;
import ray.math.Vec3;
import ray.shading.Effect;

/**
 * A triangle's data and everything about it but the ray test, which the student's {@link Triangle}
 * adds: vertices v0, v1, v2, optional vertex normals n0, n1, n2 whose barycentric blend is then
 * the shading normal, and texture coordinates vt0, vt1, vt2 (u, v in x and y; all zero unless a
 * mesh's {@code vt} lines or the scene give them).
 */
public abstract class TriangleShape extends Surface {
    protected Vec3 v0 = Vec3.ZERO;
    protected Vec3 v1 = new Vec3(1, 0, 0);
    protected Vec3 v2 = new Vec3(0, 1, 0);
    /** The vertices' texture coordinates: (u, v, w) as an OBJ file's {@code vt} gives them, w unused. */
    protected Vec3 vt0 = Vec3.ZERO;
    protected Vec3 vt1 = Vec3.ZERO;
    protected Vec3 vt2 = Vec3.ZERO;
    /** Vertex normals, or null for a flat triangle. */
    private Vec3 n0;
    private Vec3 n1;
    private Vec3 n2;
    /**
     * Whether the vertices span no area (collinear, repeated, or not finite); set by complete().
     * The face normal itself is not stored: a mesh has millions of triangles and only the hit ones
     * need it, so it is computed per hit (see {@link #getFaceNormal()}), which saves a Vec3 (40
     * bytes) per triangle.
     */
    private boolean degenerate;

    protected TriangleShape() {
    }

    protected TriangleShape(Vec3 v0, Vec3 v1, Vec3 v2) {
        this.v0 = v0;
        this.v1 = v1;
        this.v2 = v2;
        complete();
    }

    protected TriangleShape(Vec3 v0, Vec3 v1, Vec3 v2, Vec3 n0, Vec3 n1, Vec3 n2) {
        this(v0, v1, v2);
        this.n0 = n0;
        this.n1 = n1;
        this.n2 = n2;
    }

    public void setV0(Vec3 v0) {
        this.v0 = v0;
    }

    public void setV1(Vec3 v1) {
        this.v1 = v1;
    }

    public void setV2(Vec3 v2) {
        this.v2 = v2;
    }

    public void setVt0(Vec3 vt0) {
        this.vt0 = vt0;
    }

    public void setVt1(Vec3 vt1) {
        this.vt1 = vt1;
    }

    public void setVt2(Vec3 vt2) {
        this.vt2 = vt2;
    }

    public Vec3 getVt0() {
        return vt0;
    }

    public Vec3 getVt1() {
        return vt1;
    }

    public Vec3 getVt2() {
        return vt2;
    }

    public Vec3 getV0() {
        return v0;
    }

    public Vec3 getV1() {
        return v1;
    }

    public Vec3 getV2() {
        return v2;
    }

    public boolean hasVertexNormals() {
        return n0 != null;
    }

    @Override
    public Set<Effect> effects() {
        return n0 != null ? Set.of(Effect.VERTEX_NORMALS) : Set.of();
    }

    /** Whether the triangle spans no area, so that no ray can hit it (known after complete()). */
    public boolean isDegenerate() {
        return degenerate;
    }

    /** normalize((v1 − v0) × (v2 − v0)), or the zero vector for a degenerate triangle. */
    public Vec3 getFaceNormal() {
        Vec3 cross = edgeCross();
        return spansArea(cross) ? cross.normalized() : Vec3.ZERO;
    }

    /** (v1 − v0) × (v2 − v0): the unnormalized face normal, twice the area in length. */
    private Vec3 edgeCross() {
        return v1.minus(v0).cross(v2.minus(v0));
    }

    /** Whether an edge cross product is a usable normal: finite, and not zero or underflowed to zero. */
    private static boolean spansArea(Vec3 cross) {
        return cross.isFinite() && cross.lengthSquared() > 0;
    }

    /**
     * Computes the face normal. A triangle without area (collinear or repeated vertices, a
     * non-finite coordinate, or an edge cross product that underflows to zero or overflows) is
     * degenerate: its face normal is the zero vector (never NaN), and {@link #isDegenerate()}
     * lets intersect reject it at once, since no ray can hit it.
     */
    @Override
    public Surface complete() {
        degenerate = !spansArea(edgeCross());
        return this;
    }

    /** The same triangle, vertex normals and texture coordinates with its vertices moved (normals do not move). */
    @Override
    public Surface inFrameAt(Vec3 origin) {
        TriangleShape moved = (TriangleShape) copy();
        moved.v0 = v0.minus(origin);
        moved.v1 = v1.minus(origin);
        moved.v2 = v2.minus(origin);
        return moved.complete();
    }

    /** The unit normal at barycentric coordinates (beta, gamma): the face normal, or the blend of vertex normals. */
    public Vec3 normalAt(double beta, double gamma) {
        if (n0 == null) {
            return getFaceNormal();
        }
        Vec3 blend = n0.times(1 - beta - gamma).plus(n1.times(beta)).plus(n2.times(gamma)).normalized();
        // Normals that cancel out, or NaN/infinite inputs, fall back to the face normal (finite by complete()).
        return blend.isFinite() && blend.lengthSquared() > 0 ? blend : getFaceNormal();
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
    public HitGeometry hitGeometry(IntersectionRecord hit) {
        Vec3 p = hit.location;
        Vec3 n = getFaceNormal();
        Vec3 e1 = v1.minus(v0);
        Vec3 e2 = v2.minus(v0);
        double coordinates = Math.max(Math.max(v0.maxAbs(), v1.maxAbs()), Math.max(v2.maxAbs(), p.maxAbs()));
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
    public Bounds bounds() {
        return Bounds.of(v0, v1, v2);
    }

    @Override
    public String toString() {
        return "Triangle[" + v0 + ", " + v1 + ", " + v2 + "]";
    }

    @Override
    public SurfaceKind kind() {
        return SurfaceKind.TRIANGLE;
    }

    @Override
    public String describe(DoubleFunction<String> number) {
        return "Triangle " + vec(v0, number) + ", " + vec(v1, number) + ", " + vec(v2, number);
    }

    /** Any placement maps a triangle to a triangle. */
    @Override
    public void sketch(Sketch sketch, Affine toWorld) {
        sketch.triangle(toWorld.applyToPoint(v0), toWorld.applyToPoint(v1), toWorld.applyToPoint(v2));
    }
}
