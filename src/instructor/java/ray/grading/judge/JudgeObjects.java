package ray.grading.judge;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import ray.bvh.BvhNode;
import ray.grading.wire.FrameworkFields;
import ray.grading.wire.Protocol;
import ray.grading.wire.Refs;
import ray.grading.wire.Trees;
import ray.grading.wire.WireError;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;
import ray.image.Image;
import ray.math.Bounds;
import ray.math.Affine;
import ray.math.Vec3;
import ray.surface.Surface;
import ray.surface.Transformed;
import ray.surface.Triangle;
import ray.surface.TriangleSet;

/**
 * The judge's names for objects in one worker: a handle per stand-in (its twin's), per judge-side
 * surface a twin holds, per texture image. Writing a reference to one of them in a message first
 * writes whatever the worker does not yet have of it into the message's definitions: the twin to
 * make, its framework state when that changed, a complete() to run, a surface's bounds, an image's
 * texels. A new worker starts with none of them ({@link #forget}).
 */
final class JudgeObjects {
    private int generation;
    private int nextHandle = 1;
    private final List<Object> byHandle = new ArrayList<>(List.of(new Object()));
    private final Map<Surface, Integer> judgeSurfaces = new IdentityHashMap<>();
    /** The nodes of students' trees the worker has been sent ({@link Protocol#DEF_NODES}). */
    private final Map<BvhNode, Integer> nodes = new IdentityHashMap<>();
    private final Map<Image, Integer> images = new IdentityHashMap<>();
    /** The judge's objects the worker builds again (placements, sets of triangles), named by REF_PLACED. */
    private final Map<Object, Boolean> builtAgain = new IdentityHashMap<>();
    /** Surfaces the student's code made, as the judge shows them (one per class name). */
    private final Map<String, ForeignSurface> foreign = new java.util.HashMap<>();
    private final Certification certification;

    JudgeObjects(Certification certification) {
        this.certification = certification;
    }

    Certification certification() {
        return certification;
    }

    int generation() {
        return generation;
    }

    /** A new worker: no handle of the old one means anything there. */
    void forget() {
        generation++;
        nextHandle = 1;
        byHandle.subList(1, byHandle.size()).clear();
        judgeSurfaces.clear();
        nodes.clear();
        images.clear();
        builtAgain.clear();
    }

    /** A message being written: definitions first, then the body. */
    final class Message implements Refs {
        private final WireOut definitions = new WireOut();
        private int definitionCount;
        final WireOut body = new WireOut();
        /** Stand-ins whose state is being written now or was in this message: each is sent once (a group that holds itself too). */
        private final Map<Object, Boolean> sending = new IdentityHashMap<>();

        /** The whole message: the definitions' count, the definitions, the body. */
        WireOut assembled() {
            WireOut whole = new WireOut();
            whole.i32(definitionCount);
            appendRaw(whole, definitions);
            appendRaw(whole, body);
            return whole;
        }

        /** Names a stand-in as a call's target (a twin reference), sending what the worker needs of it first. */
        void target(StandIn standIn) {
            body.u8(Protocol.REF_TWIN).i32(sync(standIn));
        }

        /** The twin's handle, after writing every definition the worker still needs for it. */
        int sync(StandIn standIn) {
            StandInState s = standIn.ray1StandIn();
            if (s.generation != generation) {
                s.generation = generation;
                s.handle = nextHandle++;
                s.sentState = null;
                byHandle.add(standIn);
                definitionCount++;
                definitions.u8(Protocol.DEF_TWIN).i32(s.handle).str(standIn.ray1StudentClass());
                // A new twin runs complete() if the stand-in ever did (the student's complete() may keep something).
                s.completePending = s.completed;
            }
            if (sending.containsKey(standIn)) {
                return s.handle;
            }
            sending.put(standIn, true);
            {
                WireOut state = new WireOut();
                FrameworkFields.write(standIn, studentClassOf(standIn), state, this);
                byte[] bytes = state.toByteArray();
                if (s.sentState == null || !Arrays.equals(bytes, s.sentState)) {
                    definitionCount++;
                    definitions.u8(Protocol.DEF_STATE).i32(s.handle).str(standIn.ray1StudentClass());
                    appendRaw(definitions, state);
                    s.sentState = bytes;
                }
                if (s.completePending) {
                    definitionCount++;
                    definitions.u8(Protocol.DEF_COMPLETE).i32(s.handle);
                    s.completePending = false;
                }
            }
            return s.handle;
        }

        @Override
        public void writeSurface(WireOut out, Surface surface) {
            if (surface == null) {
                out.u8(Protocol.REF_NULL);
            } else if (StudentCalls.isRemote(surface)) {
                out.u8(Protocol.REF_TWIN).i32(sync((StandIn) surface));
            } else if (surface instanceof ForeignSurface) {
                // What the student's code made is not the judge's to send back: the worker gets nothing in its place.
                out.u8(Protocol.REF_NULL);
            } else if (surface instanceof Transformed && certification.holdsStandIn(surface)) {
                out.u8(Protocol.REF_PLACED).i32(placedHandle((Transformed) surface));
            } else if (surface instanceof TriangleSet && certification.holdsStandIn(surface)) {
                out.u8(Protocol.REF_PLACED).i32(trianglesHandle((TriangleSet) surface));
            } else {
                out.u8(Protocol.REF_JUDGE).i32(judgeHandle(surface));
            }
        }

        /** A placement of a student's object: built again in the worker, over the placed surface's own reference. */
        private int placedHandle(Transformed placed) {
            Integer known = judgeSurfaces.get(placed);
            if (known != null) {
                return known;
            }
            int handle = nextHandle++;
            judgeSurfaces.put(placed, handle);
            byHandle.add(placed);
            builtAgain.put(placed, true);
            WireOut definition = new WireOut();
            writeSurface(definition, placed.placed());
            Affine toWorld = placed.toWorld();
            for (double x : toWorld.linear()) {
                definition.f64(x);
            }
            Vec3 t = toWorld.translationPart();
            definition.f64(t.x).f64(t.y).f64(t.z);
            definitionCount++;
            definitions.u8(Protocol.DEF_PLACED).i32(handle);
            appendRaw(definitions, definition);
            return handle;
        }

        /**
         * A node of a students' tree, as the worker names it: the nodes under it that the worker lacks
         * are sent first, children before parents, each with its box and its range or children.
         */
        int nodeHandle(BvhNode root) {
            Integer known = nodes.get(root);
            if (known != null) {
                return known;
            }
            java.util.List<BvhNode> unsent = new java.util.ArrayList<>();
            java.util.Deque<BvhNode> pending = new java.util.ArrayDeque<>();
            java.util.Set<BvhNode> seen = java.util.Collections.newSetFromMap(new IdentityHashMap<>());
            pending.push(root);
            while (!pending.isEmpty()) {
                BvhNode node = pending.pop();
                if (nodes.containsKey(node) || !seen.add(node)) {
                    continue;
                }
                unsent.add(node);
                if (!node.isLeaf()) {
                    pending.push(node.left);
                    pending.push(node.right);
                }
            }
            // Parents were listed before their children: send the list backwards, so each child is known first.
            definitionCount++;
            definitions.u8(Protocol.DEF_NODES).i32(unsent.size());
            for (int k = unsent.size() - 1; k >= 0; k--) {
                BvhNode node = unsent.get(k);
                int handle = nextHandle++;
                byHandle.add(node);
                nodes.put(node, handle);
                definitions.i32(handle);
                Trees.writeNode(definitions, node, nodes::get);
            }
            return nodes.get(root);
        }

        /** A question's target: a stand-in's twin, or what the worker builds again (a set of its triangles, a placement of one). */
        int target(Object target) {
            if (target instanceof StandIn) {
                return sync((StandIn) target);
            }
            return target instanceof TriangleSet ? trianglesHandle((TriangleSet) target) : placedHandle((Transformed) target);
        }

        /** A set of stand-in triangles, built again in the worker over their twins, in order. */
        private int trianglesHandle(TriangleSet set) {
            Integer known = judgeSurfaces.get(set);
            if (known != null) {
                return known;
            }
            List<Triangle> triangles = set.triangles();
            int[] parts = new int[triangles.size()];
            for (int k = 0; k < parts.length; k++) {
                parts[k] = sync((StandIn) triangles.get(k));
            }
            int handle = nextHandle++;
            judgeSurfaces.put(set, handle);
            byHandle.add(set);
            builtAgain.put(set, true);
            definitionCount++;
            definitions.u8(Protocol.DEF_TRIANGLES).i32(handle).i32(parts.length);
            for (int part : parts) {
                definitions.i32(part);
            }
            return handle;
        }

        int judgeHandle(Surface surface) {
            Integer known = judgeSurfaces.get(surface);
            if (known != null) {
                return known;
            }
            int handle = nextHandle++;
            judgeSurfaces.put(surface, handle);
            byHandle.add(surface);
            Bounds b;
            try {
                b = surface.bounds();
            } catch (RuntimeException e) {
                b = Bounds.EVERYTHING;
            }
            definitionCount++;
            definitions.u8(Protocol.DEF_JUDGE).i32(handle).f64(b.minX).f64(b.minY).f64(b.minZ).f64(b.maxX).f64(b.maxY).f64(b.maxZ)
                    .bool(certification.certified(surface));
            return handle;
        }

        @Override
        public Surface readSurface(WireIn in) {
            return JudgeObjects.this.readSurface(in);
        }

        @Override
        public void writeImage(WireOut out, Image image) {
            if (image == null) {
                out.i32(-1);
                return;
            }
            Integer known = images.get(image);
            if (known == null) {
                known = images.size();
                images.put(image, known);
                definitionCount++;
                definitions.u8(Protocol.DEF_IMAGE).i32(known).i32(image.width()).i32(image.height());
                for (int j = 0; j < image.height(); j++) {
                    for (int i = 0; i < image.width(); i++) {
                        Vec3 c = image.get(i, j);
                        definitions.f64(c.x).f64(c.y).f64(c.z);
                    }
                }
            }
            out.i32(known);
        }

        @Override
        public Image readImage(WireIn in) {
            throw new WireError("the worker sends no images");
        }
    }

    /** The stand-in's class that stands for the student's (a test's subclass of it extends it). */
    private static Class<?> studentClassOf(StandIn standIn) {
        Class<?> c = standIn.getClass();
        while (c != null && !c.getName().equals(standIn.ray1StudentClass())) {
            c = c.getSuperclass();
        }
        if (c == null) {
            throw new IllegalStateException(standIn.getClass() + " does not extend " + standIn.ray1StudentClass());
        }
        return c;
    }

    /** Refs for reading the worker's answers (they name objects; they define none). */
    Refs reader() {
        return new Refs() {
            @Override
            public void writeSurface(WireOut out, Surface surface) {
                throw new UnsupportedOperationException();
            }

            @Override
            public Surface readSurface(WireIn in) {
                return JudgeObjects.this.readSurface(in);
            }

            @Override
            public void writeImage(WireOut out, Image image) {
                throw new UnsupportedOperationException();
            }

            @Override
            public Image readImage(WireIn in) {
                throw new WireError("the worker sends no images");
            }
        };
    }

    /** The judge's object a worker names: a stand-in by its twin, a judge surface, or what the student's code made. */
    Surface readSurface(WireIn in) {
        int kind = in.u8();
        switch (kind) {
            case Protocol.REF_NULL:
                return null;
            case Protocol.REF_TWIN: {
                Object o = byHandle(in.i32());
                if (!StudentCalls.isRemote(o) || !(o instanceof Surface)) {
                    throw new WireError("the worker named a twin that is no surface");
                }
                return (Surface) o;
            }
            case Protocol.REF_JUDGE:
            case Protocol.REF_PLACED: {
                Object o = byHandle(in.i32());
                if (StudentCalls.isRemote(o) || !(o instanceof Surface) || (kind == Protocol.REF_PLACED) != builtAgain.containsKey(o)) {
                    throw new WireError("the worker named a judge surface it was never given");
                }
                return (Surface) o;
            }
            case Protocol.REF_FOREIGN: {
                String className = in.str(Protocol.MAX_NAME_BYTES);
                if (className == null || !className.matches("[\\p{L}\\p{N}_$.]{1,200}")) {
                    throw new WireError("a surface of a class with no Java name");
                }
                return foreign.computeIfAbsent(className, ForeignSurface::new);
            }
            default:
                throw new WireError("a surface named by kind " + kind);
        }
    }

    /** The judge-side surface a worker's callback names. */
    Surface readJudgeSurface(int handle) {
        Object o = byHandle(handle);
        if (StudentCalls.isRemote(o) || !(o instanceof Surface)) {
            throw new WireError("the worker called back a judge surface it was never given");
        }
        return (Surface) o;
    }

    /** The tree stand-in a primitive callback names: one of the graded task's (a twin the worker holds). */
    ray.bvh.TreeData readTree(int handle) {
        Object o = byHandle(handle);
        if (!StudentCalls.isRemote(o) || !(o instanceof ray.bvh.TreeData)) {
            throw new WireError("the worker named a twin that is no tree");
        }
        return (ray.bvh.TreeData) o;
    }

    private Object byHandle(int handle) {
        if (handle <= 0 || handle >= byHandle.size()) {
            throw new WireError("the worker named handle " + handle + ", which it was never given");
        }
        return byHandle.get(handle);
    }

    private static void appendRaw(WireOut to, WireOut from) {
        to.raw(from);
    }
}
