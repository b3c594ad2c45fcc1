package ray.surface;

import ray.math.Vec3;

/**
 * A triangle's data, for the student's {@link Triangle}, which adds the ray test: vertices v0, v1,
 * v2, optional vertex normals n0, n1, n2 whose barycentric blend is then the shading normal
 * ({@link #normalAt}), and texture coordinates vt0, vt1, vt2 (u, v in x and y; all zero unless a
 * mesh's {@code vt} lines or the scene give them). (What the framework knows of a triangle besides
 * is in {@link TriangleFacts}.)
 */
public abstract class TriangleSurface extends Surface {
    protected Vec3 v0 = Vec3.ZERO;
    protected Vec3 v1 = new Vec3(1, 0, 0);
    protected Vec3 v2 = new Vec3(0, 1, 0);
    /** The vertices' texture coordinates: (u, v, w) as an OBJ file's {@code vt} gives them, w unused. */
    protected Vec3 vt0 = Vec3.ZERO;
    protected Vec3 vt1 = Vec3.ZERO;
    protected Vec3 vt2 = Vec3.ZERO;
    /** Vertex normals, or null for a flat triangle. */
    Vec3 n0;
    Vec3 n1;
    Vec3 n2;
    /** Whether the vertices span no area; set by complete() ({@link TriangleFacts#complete}). */
    boolean degenerate;

    protected TriangleSurface() {
    }

    protected TriangleSurface(Vec3 v0, Vec3 v1, Vec3 v2) {
        this.v0 = v0;
        this.v1 = v1;
        this.v2 = v2;
        complete();
    }

    protected TriangleSurface(Vec3 v0, Vec3 v1, Vec3 v2, Vec3 n0, Vec3 n1, Vec3 n2) {
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

    /**
     * Whether the triangle spans no area (collinear or repeated vertices, a non-finite coordinate,
     * or an edge cross product that underflows to zero or overflows), so that no ray can hit it:
     * known once the triangle is complete (the scene loader and the constructors with vertices
     * complete it), so an intersect can reject such a triangle at once.
     */
    public boolean isDegenerate() {
        return degenerate;
    }

    /**
     * normalize((v1 − v0) × (v2 − v0)), or the zero vector for a triangle without area (collinear or
     * repeated vertices, a non-finite coordinate, or an edge cross product that underflows to zero or
     * overflows), never NaN. The face normal is not stored: a mesh has millions of triangles and only
     * the hit ones need it, so it is computed per hit, which saves a Vec3 (40 bytes) per triangle.
     */
    public Vec3 getFaceNormal() {
        Vec3 cross = v1.minus(v0).cross(v2.minus(v0));
        return TriangleFacts.spansArea(cross) ? cross.normalized() : Vec3.ZERO;
    }

    /** The unit normal at barycentric coordinates (beta, gamma): the face normal, or the blend of vertex normals. */
    public Vec3 normalAt(double beta, double gamma) {
        if (n0 == null) {
            return getFaceNormal();
        }
        Vec3 blend = n0.times(1 - beta - gamma).plus(n1.times(beta)).plus(n2.times(gamma)).normalized();
        // Normals that cancel out, or NaN/infinite inputs, fall back to the face normal (finite by construction).
        return blend.isFinite() && blend.lengthSquared() > 0 ? blend : getFaceNormal();
    }
}
