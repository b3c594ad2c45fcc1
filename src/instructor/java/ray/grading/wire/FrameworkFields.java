package ray.grading.wire;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import ray.accel.Hittable;
import ray.bvh.BoundingBoxes;
import ray.bvh.Box;
import ray.image.Image;
import ray.math.Vec3;
import ray.render.HitShading;
import ray.shading.Brdf;
import ray.shading.Fresnel;
import ray.shading.MicrofacetDistribution;
import ray.shading.Texture;
import ray.surface.Surface;

/**
 * The state of a student object that the framework keeps: the fields of the framework classes the
 * student's class extends (a sphere's center and radius, a triangle's vertices, a camera's view and
 * basis, a texture's image, a group's surfaces). The judge's stand-in holds them as the tests and
 * the loader set them; the worker's twin gets the same values before each call, so the student's
 * code sees the object the test made. The student's own fields live only in the twin.
 *
 * <p>Both sides list the fields the same way, from the same framework classes: the topmost class
 * first, each class's fields by name. A surface's shader stays behind (no student method uses it,
 * and shaders are not data), and so does a shader's texture: each shade call carries the texture's
 * color at its hit instead, looked up on the judge's side ({@link Protocol#OP_SHADE}); and so does a
 * 2019 shader's BRDF, whose values the worker asks back ({@link Protocol#CB_BRDF}); and so does a
 * ray tracer's shading of hits, which the worker asks back ({@link Protocol#CB_SHADE_HIT}). A field
 * of a type this class cannot send fails at once, so a framework change that adds one is noticed by
 * the grader's own tests.
 */
public final class FrameworkFields {
    private static final Map<Class<?>, List<Field>> FIELDS = new ConcurrentHashMap<>();
    /** The longest name a framework field may hold (a shader's name from the scene file), in UTF-8 bytes. */
    private static final int MAX_NAME_BYTES = 4096;

    private FrameworkFields() {
    }

    /** The framework's fields of {@code studentClass}: those of its superclasses, below Object. */
    public static List<Field> of(Class<?> studentClass) {
        return FIELDS.computeIfAbsent(studentClass, FrameworkFields::list);
    }

    private static List<Field> list(Class<?> studentClass) {
        List<Class<?>> chain = new ArrayList<>();
        for (Class<?> c = studentClass.getSuperclass(); c != null && c != Object.class; c = c.getSuperclass()) {
            chain.add(0, c);
        }
        List<Field> fields = new ArrayList<>();
        for (Class<?> c : chain) {
            List<Field> declared = new ArrayList<>();
            for (Field f : c.getDeclaredFields()) {
                if (Modifier.isStatic(f.getModifiers()) || f.isSynthetic() || (c == Surface.class && f.getName().equals("shader"))
                        || f.getType() == Texture.class || f.getType() == HitShading.class || f.getType() == Brdf.class
                        // a microfacet BRDF's D, G1 and F objects: each side makes its own from the fields' names and numbers
                        || f.getType() == MicrofacetDistribution.class || f.getType() == Fresnel.class
                        // a tree's counts (each side counts its own: the judge the primitive tests it serves, a search's
                        // answer the box tests the worker made)
                        // and its box tests (the student's own class, which each side makes)
                        || f.getType() == long.class || f.getType() == BoundingBoxes.class) {
                    continue;
                }
                check(f);
                f.setAccessible(true);
                declared.add(f);
            }
            declared.sort(Comparator.comparing(Field::getName));
            fields.addAll(declared);
        }
        return List.copyOf(fields);
    }

    private static void check(Field f) {
        Class<?> t = f.getType();
        if (t != double.class && t != int.class && t != boolean.class && t != Vec3.class && t != Image.class && t != List.class
                && t != Surface.class && t != String.class && t != int[].class && t != Box[].class && t != Hittable[].class) {
            throw new IllegalStateException("grading cannot send " + f.getDeclaringClass().getName() + "." + f.getName()
                    + " of type " + t.getName() + "; teach ray.grading.wire.FrameworkFields that type");
        }
    }

    /** Writes {@code object}'s framework fields, those of the student class {@code studentClass} it is (or extends). */
    public static void write(Object object, Class<?> studentClass, WireOut out, Refs refs) {
        for (Field f : of(studentClass)) {
            try {
                Class<?> t = f.getType();
                if (t == double.class) {
                    out.f64(f.getDouble(object));
                } else if (t == int.class) {
                    out.i32(f.getInt(object));
                } else if (t == boolean.class) {
                    out.bool(f.getBoolean(object));
                } else if (t == Vec3.class) {
                    out.vec((Vec3) f.get(object));
                } else if (t == String.class) {
                    out.str((String) f.get(object));
                } else if (t == Image.class) {
                    refs.writeImage(out, (Image) f.get(object));
                } else if (t == Surface.class) {
                    refs.writeSurface(out, (Surface) f.get(object));
                } else if (t == int[].class) {
                    int[] ints = (int[]) f.get(object);
                    out.i32(ints.length);
                    for (int value : ints) {
                        out.i32(value);
                    }
                } else if (t == Box[].class) {
                    Box[] boxes = (Box[]) f.get(object);
                    out.i32(boxes.length);
                    for (Box box : boxes) {
                        Trees.writeBox(out, box);
                    }
                } else if (t == Hittable[].class) {
                    // A tree's primitives stay on the judge's side: the worker's copy asks each back by its place.
                    out.i32(((Hittable[]) f.get(object)).length);
                } else {
                    List<?> list = (List<?>) f.get(object);
                    out.i32(list.size());
                    for (Object part : list) {
                        refs.writeSurface(out, (Surface) part);
                    }
                }
            } catch (IllegalAccessException e) {
                throw new IllegalStateException(e);
            }
        }
    }

    /** A surface as a state names it: decoded now, found when the state is applied. */
    public static final class SurfaceName {
        public final int kind;
        public final int handle;

        public SurfaceName(int kind, int handle) {
            this.kind = kind;
            this.handle = handle;
        }
    }

    /**
     * Decodes a state written by {@link #write} for an object of {@code type}, without touching any
     * object: numbers, vectors and images as they are, a surface as a {@link SurfaceName}, a list as
     * a list. {@link #apply} sets them later (on the worker, in the call that needs them, since
     * making the object runs the student's code).
     */
    public static List<Object> readValues(Class<?> type, WireIn in, Refs refs) {
        List<Field> fields = of(type);
        List<Object> values = new ArrayList<>(fields.size());
        for (Field f : fields) {
            Class<?> t = f.getType();
            if (t == double.class) {
                values.add(in.f64());
            } else if (t == int.class) {
                values.add(in.i32());
            } else if (t == boolean.class) {
                values.add(in.bool());
            } else if (t == Vec3.class) {
                values.add(in.vec());
            } else if (t == String.class) {
                values.add(in.str(MAX_NAME_BYTES));
            } else if (t == Image.class) {
                values.add(refs.readImage(in));
            } else if (t == Surface.class) {
                int kind = in.u8();
                values.add(new SurfaceName(kind, kind == Protocol.REF_NULL ? 0 : in.i32()));
            } else if (t == int[].class) {
                int[] ints = new int[in.count(Protocol.MAX_ENTRIES, f.getName())];
                for (int k = 0; k < ints.length; k++) {
                    ints[k] = in.i32();
                }
                values.add(ints);
            } else if (t == Box[].class) {
                Box[] boxes = new Box[in.count(Protocol.MAX_ENTRIES, f.getName())];
                for (int k = 0; k < boxes.length; k++) {
                    boxes[k] = Trees.readBox(in);
                }
                values.add(boxes);
            } else if (t == Hittable[].class) {
                values.add(new PrimitiveCount(in.count(Protocol.MAX_ENTRIES, f.getName())));
            } else {
                int n = in.count(Protocol.MAX_PARTS, f.getName());
                List<SurfaceName> parts = new ArrayList<>(n);
                for (int k = 0; k < n; k++) {
                    int kind = in.u8();
                    parts.add(new SurfaceName(kind, kind == Protocol.REF_NULL ? 0 : in.i32()));
                }
                values.add(parts);
            }
        }
        return values;
    }

    /** How many primitives a tree holds on the judge's side: the worker makes that many that ask back ({@link #apply}). */
    public static final class PrimitiveCount {
        public final int count;

        PrimitiveCount(int count) {
            this.count = count;
        }
    }

    /**
     * Sets {@code object}'s framework fields to {@code values} ({@link #readValues}), each named surface
     * found by {@code find}, and a tree's primitives made by {@code primitives} from their count.
     */
    @SuppressWarnings("unchecked")
    public static void apply(Object object, List<Object> values, java.util.function.Function<SurfaceName, Surface> find,
            java.util.function.IntFunction<Hittable[]> primitives) {
        List<Field> fields = of(object.getClass());
        for (int k = 0; k < fields.size(); k++) {
            Field f = fields.get(k);
            Object value = values.get(k);
            try {
                if (f.getType() == List.class) {
                    List<Surface> parts = new ArrayList<>();
                    for (SurfaceName name : (List<SurfaceName>) value) {
                        parts.add(find.apply(name));
                    }
                    // A final list (a group's surfaces) is refilled rather than replaced.
                    List<Surface> list = (List<Surface>) f.get(object);
                    if (list != null && Modifier.isFinal(f.getModifiers())) {
                        list.clear();
                        list.addAll(parts);
                    } else {
                        f.set(object, parts);
                    }
                } else if (f.getType() == Surface.class) {
                    f.set(object, find.apply((SurfaceName) value));
                } else if (f.getType() == Hittable[].class) {
                    f.set(object, primitives.apply(((PrimitiveCount) value).count));
                } else {
                    f.set(object, value);
                }
            } catch (IllegalAccessException e) {
                throw new IllegalStateException(e);
            }
        }
    }
}
