package ray.grading.worker;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import ray.grading.wire.FrameworkFields;
import ray.grading.wire.Protocol;
import ray.grading.wire.Refs;
import ray.grading.wire.ThrownData;
import ray.grading.wire.WireError;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;
import ray.image.Image;
import ray.math.Affine;
import ray.math.Bounds;
import ray.math.Vec3;
import ray.surface.Surface;
import ray.surface.Transformed;

/**
 * The worker's objects, by the handles the judge gave them: twins (instances of the student's
 * classes, one per stand-in on the judge's side), proxies of the judge's surfaces that twins hold (a
 * group's children), and texture images.
 *
 * <p>Reading a message's definitions runs no student code: a twin to make, its state and a
 * complete() to run are noted, and {@link #settle} does them inside the call that follows, so that
 * whatever the student's constructor, static initializer or complete() throws is that call's answer,
 * as the test that made the object would have seen it. A twin whose making threw stays broken:
 * every later use throws the same.
 */
final class WorkerObjects implements Refs {
    private final Map<Integer, Object> twins = new HashMap<>();
    private final Map<Object, Integer> handles = new IdentityHashMap<>();
    private final Map<Integer, ThrownData> broken = new HashMap<>();
    private final Map<Integer, JudgeSurface> proxies = new HashMap<>();
    /** Placements of twins (the framework's Transformed), built here as on the judge's side. */
    private final Map<Integer, Surface> placed = new HashMap<>();
    private final Map<Object, Integer> placedHandles = new IdentityHashMap<>();
    private final Map<Integer, Image> images = new HashMap<>();
    private final Map<Integer, ray.bvh.BvhNode> nodes = new HashMap<>();
    /** What the definitions asked for and {@link #settle} has not yet done, in order. */
    private final List<Runnable> unsettled = new ArrayList<>();
    private final JudgeLink link;

    WorkerObjects(JudgeLink link) {
        this.link = link;
    }

    /** Reads a message's definitions block (a count, then each definition). */
    void define(WireIn in) {
        int n = in.count(Protocol.MAX_ENTRIES, "definitions");
        for (int k = 0; k < n; k++) {
            int kind = in.u8();
            switch (kind) {
                case Protocol.DEF_TWIN: {
                    int handle = in.i32();
                    Class<?> type = studentClass(in.str(Protocol.MAX_NAME_BYTES));
                    unsettled.add(() -> makeTwin(handle, type));
                    break;
                }
                case Protocol.DEF_STATE: {
                    int handle = in.i32();
                    Class<?> type = studentClass(in.str(Protocol.MAX_NAME_BYTES));
                    List<Object> values = FrameworkFields.readValues(type, in, this);
                    unsettled.add(() -> {
                        Object twin = twins.get(handle);
                        if (twin != null) {
                            try {
                                FrameworkFields.apply(twin, values, this::find, count -> JudgePrimitive.array(handle, count, link, this));
                            } catch (BrokenTwin b) {
                                // It holds a broken twin: using it throws what that one's making threw.
                                twins.remove(handle);
                                handles.remove(twin);
                                broken.put(handle, b.why);
                            }
                        }
                    });
                    break;
                }
                case Protocol.DEF_COMPLETE: {
                    int handle = in.i32();
                    unsettled.add(() -> complete(handle));
                    break;
                }
                case Protocol.DEF_JUDGE: {
                    int handle = in.i32();
                    Bounds bounds = new Bounds(in.f64(), in.f64(), in.f64(), in.f64(), in.f64(), in.f64());
                    proxies.put(handle, new JudgeSurface(handle, bounds, in.bool(), link, this));
                    break;
                }
                case Protocol.DEF_IMAGE:
                    defineImage(in);
                    break;
                case Protocol.DEF_NODES:
                    defineNodes(in);
                    break;
                case Protocol.DEF_TRIANGLES: {
                    int handle = in.i32();
                    int[] parts = new int[in.count(Protocol.MAX_PARTS, "triangles")];
                    for (int t = 0; t < parts.length; t++) {
                        parts[t] = in.i32();
                    }
                    unsettled.add(() -> {
                        Surface set;
                        try {
                            List<ray.surface.Triangle> triangles = new ArrayList<>(parts.length);
                            for (int part : parts) {
                                triangles.add(twin(part, ray.surface.Triangle.class));
                            }
                            set = new MirroredTriangles(triangles);
                        } catch (BrokenTwin b) {
                            set = new BrokenSurface(b.why);
                        }
                        placed.put(handle, set);
                        placedHandles.put(set, handle);
                    });
                    break;
                }
                case Protocol.DEF_PLACED: {
                    int handle = in.i32();
                    int innerKind = in.u8();
                    FrameworkFields.SurfaceName inner = new FrameworkFields.SurfaceName(innerKind,
                            innerKind == Protocol.REF_NULL ? 0 : in.i32());
                    double[] linear = new double[9];
                    for (int k2 = 0; k2 < 9; k2++) {
                        linear[k2] = in.f64();
                    }
                    Affine toWorld = Affine.of(linear, new Vec3(in.f64(), in.f64(), in.f64()));
                    unsettled.add(() -> {
                        Surface placement;
                        try {
                            placement = new Transformed(find(inner), toWorld);
                        } catch (BrokenTwin b) {
                            placement = new Transformed(new BrokenSurface(b.why), toWorld);
                        }
                        placed.put(handle, placement);
                        placedHandles.put(placement, handle);
                    });
                    break;
                }
                default:
                    throw new WireError("a definition of kind " + kind);
            }
        }
    }

    /** Nodes of a students' tree, each after its children (framework objects: no student code runs). */
    private void defineNodes(WireIn in) {
        int n = in.count(Protocol.MAX_ENTRIES, "tree nodes");
        for (int k = 0; k < n; k++) {
            int handle = in.i32();
            if (nodes.containsKey(handle)) {
                throw new WireError("node " + handle + " sent twice");
            }
            nodes.put(handle, ray.grading.wire.Trees.readNode(in, this::node));
        }
    }

    /** A node of a students' tree the judge sent; handle 0 is null (the judge's code passed none). */
    ray.bvh.BvhNode node(int handle) {
        if (handle == 0) {
            return null;
        }
        ray.bvh.BvhNode node = nodes.get(handle);
        if (node == null) {
            throw new WireError("a tree node " + handle + " never sent");
        }
        return node;
    }

    /** Loads (without initializing: no student code runs) a class the judge names, which must be a student class here. */
    private static Class<?> studentClass(String name) {
        try {
            return Class.forName(name, false, WorkerObjects.class.getClassLoader());
        } catch (ClassNotFoundException | LinkageError e) {
            throw new WireError("no class " + name + " in the worker");
        }
    }

    /**
     * Does what the definitions asked for, in order: makes twins (the student's static initializer and
     * constructor run), gives them their state, runs their complete(). What the student's code throws
     * breaks that twin; the rest goes on.
     */
    void settle() {
        for (int k = 0; k < unsettled.size(); k++) {
            unsettled.get(k).run();
        }
        unsettled.clear();
    }

    private void makeTwin(int handle, Class<?> type) {
        if (twins.containsKey(handle) || broken.containsKey(handle)) {
            throw new WireError("twin " + handle + " made twice");
        }
        try {
            Class.forName(type.getName(), true, type.getClassLoader());
            Object twin = type.getDeclaredConstructor().newInstance();
            twins.put(handle, twin);
            handles.put(twin, handle);
        } catch (java.lang.reflect.InvocationTargetException e) {
            broken.put(handle, ThrownData.of(e.getCause(), WorkerMain.OWN_PACKAGE));
        } catch (Throwable e) { // the student's class: an initializer may throw anything, an Error too
            broken.put(handle, ThrownData.of(e, WorkerMain.OWN_PACKAGE));
        }
    }

    private void complete(int handle) {
        Object twin = twins.get(handle);
        if (twin == null) {
            return;
        }
        try {
            twin.getClass().getMethod("complete").invoke(twin);
        } catch (java.lang.reflect.InvocationTargetException e) {
            twins.remove(handle);
            handles.remove(twin);
            broken.put(handle, ThrownData.of(e.getCause(), WorkerMain.OWN_PACKAGE));
        } catch (ReflectiveOperationException e) {
            throw new WireError("no complete() on " + twin.getClass().getName());
        }
    }

    private void defineImage(WireIn in) {
        int id = in.i32();
        int width = in.count(1 << 14, "image width");
        int height = in.count(1 << 14, "image height");
        if (width == 0 || height == 0 || (long) width * height > (1 << 24)) {
            throw new WireError("an image of " + width + "×" + height);
        }
        Image image = new Image(width, height);
        for (int j = 0; j < height; j++) {
            for (int i = 0; i < width; i++) {
                image.set(i, j, new Vec3(in.f64(), in.f64(), in.f64()));
            }
        }
        images.put(id, image);
    }

    /** The twin of {@code handle}, of type {@code type}; throws what its making threw when it is broken. */
    <T> T twin(int handle, Class<T> type) {
        ThrownData why = broken.get(handle);
        if (why != null) {
            throw new BrokenTwin(why);
        }
        Object twin = twins.get(handle);
        if (!type.isInstance(twin)) {
            throw new WireError("twin " + handle + " is no " + type.getSimpleName());
        }
        return type.cast(twin);
    }

    /** The surface a batch's target names: a twin, or a set built here (a placement, a set of triangles). */
    Surface target(int handle) {
        Surface built = placed.get(handle);
        return built != null ? built : twin(handle, Surface.class);
    }

    JudgeSurface proxy(int handle) {
        JudgeSurface p = proxies.get(handle);
        if (p == null) {
            throw new WireError("judge surface " + handle + " was never defined");
        }
        return p;
    }

    private Surface find(FrameworkFields.SurfaceName name) {
        switch (name.kind) {
            case Protocol.REF_NULL:
                return null;
            case Protocol.REF_TWIN:
                return twin(name.handle, Surface.class);
            case Protocol.REF_JUDGE:
                return proxy(name.handle);
            case Protocol.REF_PLACED: {
                Surface p = placed.get(name.handle);
                if (p == null) {
                    throw new WireError("placement " + name.handle + " was never defined");
                }
                return p;
            }
            default:
                throw new WireError("a surface named by kind " + name.kind);
        }
    }

    @Override
    public void writeSurface(WireOut out, Surface surface) {
        if (surface == null) {
            out.u8(Protocol.REF_NULL);
        } else if (surface instanceof JudgeSurface && proxies.get(((JudgeSurface) surface).handle) == surface) {
            out.u8(Protocol.REF_JUDGE).i32(((JudgeSurface) surface).handle);
        } else if (handles.containsKey(surface)) {
            out.u8(Protocol.REF_TWIN).i32(handles.get(surface));
        } else if (placedHandles.containsKey(surface)) {
            out.u8(Protocol.REF_PLACED).i32(placedHandles.get(surface));
        } else {
            // Something the student's code made: the judge learns only its class.
            out.u8(Protocol.REF_FOREIGN).str(Protocol.cutName(surface.getClass().getName()));
        }
    }

    @Override
    public Surface readSurface(WireIn in) {
        int kind = in.u8();
        return find(new FrameworkFields.SurfaceName(kind, kind == Protocol.REF_NULL ? 0 : in.i32()));
    }

    @Override
    public void writeImage(WireOut out, Image image) {
        throw new UnsupportedOperationException("the worker sends no images");
    }

    @Override
    public Image readImage(WireIn in) {
        int id = in.i32();
        if (id < 0) {
            return null;
        }
        Image image = images.get(id);
        if (image == null) {
            throw new WireError("image " + id + " was never defined");
        }
        return image;
    }

    /** A broken twin where a placement holds it: every search of it throws what its making threw. */
    static final class BrokenSurface extends Surface {
        private final ThrownData why;

        BrokenSurface(ThrownData why) {
            this.why = why;
        }

        @Override
        public boolean intersect(ray.IntersectionRecord out, ray.Ray ray) {
            throw new BrokenTwin(why);
        }
    }

    /** A use of a twin whose making threw: the call answers with what its making threw. */
    static final class BrokenTwin extends RuntimeException {
        private static final long serialVersionUID = 1L;
        final transient ThrownData why;

        BrokenTwin(ThrownData why) {
            super(null, null, false, false);
            this.why = why;
        }
    }
}
