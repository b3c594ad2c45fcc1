package ray.surface;

import java.util.List;
import java.util.Set;
import java.util.function.DoubleFunction;
import ray.AnswerRounds;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Acceleration;
import ray.accel.SearchCounter;
import ray.math.Affine;
import ray.math.Bounds;
import ray.math.Vec3;
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
    /** Whether rays are tested against the placed surface's box before they are mapped into it. */
    private final boolean testBounds;
    /** Counts the box tests, in a renderer's counting copy of the scene; null otherwise. */
    private final SearchCounter counter;
    /** The placed surface's box in this surface's coordinates, made when first asked. */
    private Bounds worldBounds;

    public Transformed(Surface surface, Affine toWorld) {
        this(surface, toWorld, toWorld.inverse(), true, null);
    }

    private Transformed(Surface surface, Affine toWorld, Affine toLocal, boolean testBounds, SearchCounter counter) {
        this.surface = surface;
        this.toWorld = toWorld;
        this.toLocal = toLocal;
        this.testBounds = testBounds;
        this.counter = counter;
    }

    /**
     * The same placement of the placed surface's counted copy; with acceleration a ray is tested
     * against its box first, each box test counted.
     */
    @Override
    public Surface searchCopy(Acceleration acceleration, SearchCounter counter) {
        boolean accelerated = acceleration.accelerated();
        // While grading, a placement of the student's triangles may be searched where they run (AnswerRounds).
        return AnswerRounds.searched(this, accelerated, new Transformed(surface.searchCopy(acceleration, counter), toWorld, toLocal,
                accelerated, counter));
    }

    /** The same placement, taken by a translation: the linear part stays, the translation moves by −origin (one rounding). */
    @Override
    public Surface inFrameAt(Vec3 origin) {
        return new Transformed(surface, Affine.translation(origin.negate()).after(toWorld));
    }

    public Surface placed() {
        return surface;
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
    public Bounds bounds() {
        Bounds made = worldBounds;
        if (made == null) {
            made = surface.bounds().transformed(toWorld);
            worldBounds = made; // immutable, so a race only computes it twice
        }
        return made;
    }

    /** Whether the ray may reach the placed surface at all (always, when boxes are not tested). */
    private boolean mayHit(Ray ray) {
        if (!testBounds) {
            return true;
        }
        if (counter != null) {
            counter.count(0, 1);
        }
        return bounds().mayHit(ray.origin, ray.direction, ray.start, ray.end);
    }

    /** The ray in the placed surface's coordinates (same segment: t is the same on both sides, the direction is not renormalized). */
    public Ray toLocal(Ray ray) {
        return new Ray(toLocal.applyToPoint(ray.origin), toLocal.applyToVector(ray.direction), ray.start, ray.end);
    }

    @Override
    public boolean intersectsAny(Ray ray) {
        return mayHit(ray) && surface.intersectsAny(toLocal(ray));
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        if (!mayHit(ray) || !surface.intersect(out, toLocal(ray))) {
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

    /** A placement is named as it prints: what it places and how. */
    @Override
    public String describe(DoubleFunction<String> number) {
        return toString();
    }
}
