package ray.surface;

import java.util.List;
import java.util.Set;
import java.util.function.DoubleFunction;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Acceleration;
import ray.accel.SearchCounter;
import ray.math.Affine;
import ray.math.Bounds;
import ray.math.Vec3;
import ray.shading.Effect;

/**
 * What the framework knows of one kind of surface beyond its ray test, for the defaults of
 * {@link FrameworkSurface}: these defaults are what it knows of any surface; {@link SphereFacts},
 * {@link TriangleFacts}, {@link CylinderFacts} and {@link GroupFacts} add what it knows of the
 * shapes students write the ray tests of, so that the classes those students open
 * ({@link SphereSurface}, ...) hold only the shape's data.
 */
interface ShapeFacts {
    /** The facts of any surface that is none of the student shapes. */
    ShapeFacts ANY = new ShapeFacts() {
    };

    /** The facts of {@code surface}'s kind. */
    static ShapeFacts of(Surface surface) {
        if (surface instanceof TriangleSurface) {
            return TriangleFacts.FACTS;
        }
        if (surface instanceof SphereSurface) {
            return SphereFacts.FACTS;
        }
        if (surface instanceof GroupSurface) {
            return GroupFacts.FACTS;
        }
        if (surface instanceof CylinderSurface) {
            return CylinderFacts.FACTS;
        }
        return ANY;
    }

    /** Its parts' answers, or its own intersect into a record nobody reads for a primitive. */
    default boolean intersectsAny(Surface s, Ray ray) {
        List<Surface> parts = s.children();
        if (parts.isEmpty()) {
            return s.intersect(new IntersectionRecord(), ray);
        }
        for (Surface part : parts) {
            if (part.intersectsAny(ray)) {
                return true;
            }
        }
        return false;
    }

    /** Its parts' boxes joined and placed; a primitive that does not say where it can be hit may be hit anywhere. */
    default Bounds bounds(Surface s) {
        List<Surface> parts = s.children();
        if (parts.isEmpty()) {
            return Bounds.EVERYTHING;
        }
        Bounds box = Bounds.EMPTY;
        for (Surface part : parts) {
            box = box.union(part.bounds());
        }
        return box.transformed(s.childPlacement());
    }

    default Surface complete(Surface s) {
        return s;
    }

    default List<Surface> children(Surface s) {
        return List.of();
    }

    default boolean isPrimitive(Surface s) {
        return s.children().isEmpty();
    }

    /** One test per search: a primitive, or any surface not known to be made of parts. */
    default Surface searchCopy(Surface s, Acceleration acceleration, SearchCounter counter) {
        return new CountedCopy.OneTest(s, counter);
    }

    default Set<Effect> effects(Surface s) {
        return Set.of();
    }

    /** The reported point and normal: nothing more is known of the shape. */
    default HitGeometry hitGeometry(Surface s, IntersectionRecord hit) {
        return HitGeometry.atReportedPoint(hit);
    }

    /**
     * Placed by a translation, which is exact in meaning though not in accuracy; the student shapes'
     * facts move their own numbers instead, subtracting once in double, so that rays from the camera
     * meet numbers of the scene's size rather than of its distance from the origin.
     */
    default Surface inFrameAt(Surface s, Vec3 origin) {
        return new Transformed(s, Affine.translation(origin.negate()));
    }

    /** A surface with parts names their count; any other its toString. */
    default String describe(Surface s, DoubleFunction<String> number) {
        int parts = s.children().size();
        return parts == 0 ? s.toString() : namedClass(s) + " (" + count(parts, "surface") + ")";
    }

    /** Its parts one by one, or, for a primitive that draws nothing of its own, its bounding box. */
    default void sketch(Surface s, Sketch sketch, Affine toWorld) {
        if (s.children().isEmpty()) {
            sketch.bounds(s.bounds().transformed(toWorld));
        } else {
            sketch.parts(s, toWorld.after(s.childPlacement()));
        }
    }

    default String doubtAbout(Surface s, IntersectionRecord hit, Ray ray) {
        return null;
    }

    default SurfaceKind kind() {
        return SurfaceKind.OTHER;
    }

    /** What {@code toString} says of the surface: its class's simple name. */
    default String name(Surface s) {
        return namedClass(s);
    }

    /** The simple name of the surface's class, or of the named class an anonymous one extends ("Group"). */
    static String namedClass(Surface s) {
        Class<?> named = s.getClass();
        while (named.isAnonymousClass()) {
            named = named.getSuperclass();
        }
        return named.getSimpleName();
    }

    /** "(x, y, z)", each coordinate written by {@code number}. */
    static String vec(Vec3 p, DoubleFunction<String> number) {
        return p == null ? "null" : p.format(number);
    }

    /** "12 triangles", "1 surface". */
    static String count(int n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }
}
