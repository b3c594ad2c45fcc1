package ray.grading.judge;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.bvh.BoundingBoxes;
import ray.bvh.Box;
import ray.bvh.BvhNode;
import ray.bvh.BvhTree;
import ray.camera.Camera;
import ray.grading.wire.Protocol;
import ray.grading.wire.Records;
import ray.grading.wire.ThrownData;
import ray.grading.wire.Trees;
import ray.grading.wire.WireError;
import ray.grading.wire.WireIn;
import ray.math.Vec3;
import ray.render.SceneTracer;
import ray.shading.Brdf;
import ray.shading.Fresnel;
import ray.shading.Light;
import ray.shading.MicrofacetDistribution;
import ray.shading.Shader;
import ray.shading.ShadingContext;
import ray.shading.Texture;
import ray.surface.Surface;

/**
 * What a stand-in's student method does: asks the worker to run the student's method on the
 * stand-in's twin, and returns what it returned, with the record and the ray changed as the
 * student's code changed them, or throws what it threw ({@link Rethrown}). An answer is applied only
 * once it was read whole.
 */
public final class StudentCalls {
    /** The task being graded: its classes' calls go to the worker; every other class runs as the solution. */
    private static volatile int graded;

    private StudentCalls() {
    }

    /** Whether task {@code task}'s classes are graded now. */
    public static boolean remote(int task) {
        return task == graded;
    }

    /** Whether {@code o} is an object of a class graded now (a stand-in whose calls go to the worker). */
    static boolean isRemote(Object o) {
        return o instanceof StandIn && ((StandIn) o).ray1Remote();
    }

    /** From now on, task {@code task} is graded (0: none); a change of task ends the worker of the last. */
    static void grade(int task) {
        if (task != graded) {
            graded = task;
            Worker.taskChanged(task);
        }
    }

    /** The student's {@code intersect(out, ray)} on {@code self}'s twin: in a computation's round from its answers, else at once. */
    public static boolean intersect(Surface self, IntersectionRecord out, Ray ray) {
        Rounds rounds = Rounds.deferring();
        return rounds != null ? rounds.intersect((StandIn) self, out, ray) : intersectNow(self, out, ray);
    }

    /** The student's {@code intersect(out, ray)} on {@code self}'s twin, asked at once. */
    static boolean intersectNow(Surface self, IntersectionRecord out, Ray ray) {
        return recordCall(self, out, ray, m -> {
            m.body.u8(Protocol.OP_INTERSECT);
            m.target((StandIn) self);
            Records.writeRay(m.body, ray);
            Records.write(m.body, out, m);
        }, in -> { });
    }

    /**
     * A call on {@code self}'s twin, written by {@code write}, whose answer is an intersect's (whether it
     * hit, then what it changed of the record and of the ray, then whatever {@code more} reads), asked
     * at once; the changes are applied to {@code out} and {@code ray} once the answer was read whole.
     */
    private static boolean recordCall(Object self, IntersectionRecord out, Ray ray, java.util.function.Consumer<JudgeObjects.Message> write,
            java.util.function.Consumer<WireIn> more) {
        Worker worker = Worker.get();
        IntersectionRecord changed = new IntersectionRecord();
        Ray changedRay = ray.copy();
        Outcome outcome = worker.call(write, in -> {
            int status = in.u8();
            if (status == Protocol.THREW) {
                return Outcome.threw(ThrownData.read(in));
            }
            expect(status);
            boolean hit = in.bool();
            changed.set(out);
            int mask = Records.readChanges(in, changed, worker.objects().reader());
            int rayMask = Records.readRayChanges(in, changedRay);
            more.accept(in);
            return Outcome.intersected(hit, mask, rayMask);
        });
        outcome.rethrow(self);
        Records.apply(outcome.mask, changed, out);
        if ((outcome.rayMask & Records.START) != 0) {
            ray.start = changedRay.start;
        }
        if ((outcome.rayMask & Records.END) != 0) {
            ray.end = changedRay.end;
        }
        return outcome.hit;
    }

    /** The student's {@code generateRay(u, v)} on {@code self}'s twin. */
    public static Ray generateRay(Camera self, double u, double v) {
        Rounds rounds = Rounds.deferring();
        if (rounds != null) {
            return rounds.generateRay((StandIn) self, u, v);
        }
        return (Ray) uvCall(self, Protocol.OP_GENERATE_RAY, u, v, Records::readRayOrNull);
    }

    /** The student's {@code getTexColor(u, v)} on {@code self}'s twin. */
    public static Vec3 texColor(Texture self, double u, double v) {
        Rounds rounds = Rounds.deferring();
        if (rounds != null) {
            return rounds.texColor((StandIn) self, u, v);
        }
        return (Vec3) uvCall(self, Protocol.OP_TEX_COLOR, u, v, WireIn::vec);
    }

    /** The student's BRDF {@code value(rhoD, n, l, v)} on {@code self}'s twin, asked at once. */
    public static Vec3 brdfValue(Brdf self, Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        return (Vec3) valueCall(self, Protocol.OP_BRDF_VALUE, body -> body.vec(rhoD).vec(n).vec(l).vec(v), WireIn::vec);
    }

    /** The student's microfacet distribution's {@code normalDistribution(n, h)}, D, on {@code self}'s twin, asked at once. */
    public static double normalDistribution(MicrofacetDistribution self, Vec3 n, Vec3 h) {
        return (Double) valueCall(self, Protocol.OP_MICROFACET_D, body -> body.vec(n).vec(h), WireIn::f64);
    }

    /** The student's microfacet distribution's {@code masking(x, n, h)}, G1, on {@code self}'s twin, asked at once. */
    public static double masking(MicrofacetDistribution self, Vec3 x, Vec3 n, Vec3 h) {
        return (Double) valueCall(self, Protocol.OP_MICROFACET_G1, body -> body.vec(x).vec(n).vec(h), WireIn::f64);
    }

    /** The student's Fresnel factor's {@code reflectance(cosine)}, F, on {@code self}'s twin, asked at once. */
    public static double reflectance(Fresnel self, double cosine) {
        return (Double) valueCall(self, Protocol.OP_FRESNEL, body -> body.f64(cosine), WireIn::f64);
    }

    /** The student's {@code ofSphere(center, radius)} on {@code self}'s twin: a box or null. */
    public static Box ofSphere(BoundingBoxes self, Vec3 center, double radius) {
        return (Box) valueCall(self, Protocol.OP_BOX_OF_SPHERE, body -> body.vec(center).f64(radius), Trees::readBox);
    }

    /** The student's {@code ofTriangle(a, b, c)} on {@code self}'s twin: a box or null. */
    public static Box ofTriangle(BoundingBoxes self, Vec3 a, Vec3 b, Vec3 c) {
        return (Box) valueCall(self, Protocol.OP_BOX_OF_TRIANGLE, body -> body.vec(a).vec(b).vec(c), Trees::readBox);
    }

    /** The student's {@code ofCylinder(center, radius, height)} on {@code self}'s twin: a box or null. */
    public static Box ofCylinder(BoundingBoxes self, Vec3 center, double radius, double height) {
        return (Box) valueCall(self, Protocol.OP_BOX_OF_CYLINDER, body -> body.vec(center).f64(radius).f64(height), Trees::readBox);
    }

    /** The student's slab test {@code hit(box, ray)} on {@code self}'s twin. */
    public static boolean boxHit(BoundingBoxes self, Box box, Ray ray) {
        return (Boolean) valueCall(self, Protocol.OP_BOX_HIT, body -> {
            Trees.writeBox(body, box);
            Records.writeRay(body, ray);
        }, WireIn::bool);
    }

    /**
     * The student's {@code build(start, end)} on {@code self}'s twin, whose state carries the boxes and
     * the order: the tree it returned, rebuilt here from its table, with the stand-in's order set to the
     * one the build left (so the framework's checks read both as the student's code left them).
     */
    public static BvhNode build(BvhTree self, int start, int end) {
        Object[] built = (Object[]) valueCall(self, Protocol.OP_TREE_BUILD, body -> body.i32(start).i32(end), in -> {
            int n = in.i32();
            if (n < -1 || n > Protocol.MAX_ENTRIES) {
                throw new WireError("an order of " + n + " places");
            }
            int[] order = n < 0 ? null : new int[n];
            for (int k = 0; k < n; k++) {
                order[k] = in.i32();
            }
            return new Object[] {order, Trees.readTree(in)};
        });
        Trees.setOrder(self, (int[]) built[0]);
        return (BvhNode) built[1];
    }

    /**
     * The student's {@code closestHit(node, out, ray)} on {@code self}'s twin: the nodes go as
     * definitions, each primitive test comes back ({@link Worker#servePrimitive}, which counts it), and
     * the box tests the worker's copy counted are added to the stand-in's: a test that judges the work
     * a search did reads the primitive tests, which the worker cannot misreport.
     */
    public static boolean closestHit(BvhTree self, BvhNode node, IntersectionRecord out, Ray ray) {
        long[] boxes = new long[1];
        boolean hit = recordCall(self, out, ray, m -> {
            m.body.u8(Protocol.OP_TREE_CLOSEST);
            m.target((StandIn) self);
            m.body.i32(node == null ? 0 : m.nodeHandle(node));
            Records.writeRay(m.body, ray);
            Records.write(m.body, out, m);
        }, in -> boxes[0] = in.i64());
        // Box tests as the worker counted them (they run there); primitive tests the judge counted itself as it served them.
        Trees.addCounts(self, boxes[0], 0);
        return hit;
    }

    /** The student's {@code anyHit(node, ray)} on {@code self}'s twin, as {@link #closestHit} without a record. */
    public static boolean anyHit(BvhTree self, BvhNode node, Ray ray) {
        long[] boxes = new long[1];
        Boolean hit = (Boolean) valueCall(self, Protocol.OP_TREE_ANY, body -> { }, in -> {
            boolean any = in.bool();
            boxes[0] = in.i64();
            return any;
        }, m -> {
            m.body.i32(node == null ? 0 : m.nodeHandle(node));
            Records.writeRay(m.body, ray);
        });
        Trees.addCounts(self, boxes[0], 0);
        return hit;
    }

    /** A call {@code op}(u, v) on {@code self}'s twin, asked at once: what it returned, read by {@code value}, or what it threw, rethrown. */
    private static Object uvCall(Object self, int op, double u, double v, java.util.function.Function<WireIn, Object> value) {
        return valueCall(self, op, body -> body.f64(u).f64(v), value);
    }

    /**
     * A call {@code op} on {@code self}'s twin, its arguments written by {@code arguments}, asked at
     * once: what it returned, read by {@code value}, or what it threw, rethrown.
     */
    private static Object valueCall(Object self, int op, java.util.function.Consumer<ray.grading.wire.WireOut> arguments,
            java.util.function.Function<WireIn, Object> value) {
        return valueCall(self, op, arguments, value, m -> { });
    }

    /** As above, with arguments that need the message's definitions too ({@code more}: a tree's nodes), written after the others. */
    private static Object valueCall(Object self, int op, java.util.function.Consumer<ray.grading.wire.WireOut> arguments,
            java.util.function.Function<WireIn, Object> value, java.util.function.Consumer<JudgeObjects.Message> more) {
        Outcome outcome = Worker.get().call(m -> {
            m.body.u8(op);
            m.target((StandIn) self);
            arguments.accept(m.body);
            more.accept(m);
        }, in -> returnedOrThrew(in, value));
        outcome.rethrow(self);
        return outcome.value;
    }

    /** The student's shade calls running on each thread, the innermost last: the contexts the worker's callbacks ask. */
    private static final ThreadLocal<Deque<ShadeCall>> SHADING = ThreadLocal.withInitial(ArrayDeque::new);

    /** One shade call the worker is running: the shader, the renderer's (or the test's) context, and the hit it was given. */
    static final class ShadeCall {
        final Shader shader;
        final ShadingContext context;
        final IntersectionRecord hit;

        ShadeCall(Shader shader, ShadingContext context, IntersectionRecord hit) {
            this.shader = shader;
            this.context = context;
            this.hit = hit;
        }
    }

    /** The innermost shade call running on this thread, or null. */
    static ShadeCall shading() {
        return SHADING.get().peekLast();
    }

    /**
     * The student's {@code shade(hit, ray, context, depth)} on {@code self}'s twin, asked at once (in a
     * computation too: its shadow tests and mirror rays are the judge's to trace, as the worker asks
     * them, so no answer can be guessed ahead). The lights go along as data, and the shader's texture
     * color at the hit, looked up here, so that the student's shading is judged with the solution's
     * texture; the context's shadow tests and mirror rays come back as callbacks
     * ({@link Worker#serveShading}), which may shade again (a mirror ray that meets another of the
     * student's shaders: a call inside this one).
     */
    public static Vec3 shade(Shader self, IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        Vec3 textureColor = self.getTexture() != null ? self.diffuseColorAt(hit) : null;
        List<Light> lights = context.lights();
        return colorCall(self, SHADING.get(), new ShadeCall(self, context, hit), m -> {
            m.body.u8(Protocol.OP_SHADE);
            m.target((StandIn) self);
            Records.write(m.body, hit, m);
            Records.writeRay(m.body, ray);
            m.body.i32(depth).i32(lights.size());
            for (Light light : lights) {
                m.body.vec(light.getPosition()).vec(light.getIntensity());
            }
            m.body.vec(textureColor);
        });
    }

    /** The student's shadeRay calls running on each thread, the innermost last: whose hits the worker's callbacks have shaded. */
    private static final ThreadLocal<Deque<SceneTracer>> TRACING = ThreadLocal.withInitial(ArrayDeque::new);

    /** The innermost ray tracer whose shadeRay runs on this thread, or null. */
    static SceneTracer tracing() {
        return TRACING.get().peekLast();
    }

    /**
     * The student's {@code shadeRay(ray, depth)} on {@code self}'s twin, asked at once: the twin searches
     * the judge's scene ({@link Protocol#CB_INTERSECT}) and has its hits shaded here by the stand-in's own
     * shading ({@link Worker#serveShadeHit}), which may trace mirror rays through this method again.
     */
    public static Vec3 shadeRay(SceneTracer self, Ray ray, int depth) {
        return colorCall(self, TRACING.get(), self, m -> {
            m.body.u8(Protocol.OP_SHADE_RAY);
            m.target((StandIn) self);
            Records.writeRay(m.body, ray);
            m.body.i32(depth);
        });
    }

    /**
     * A call on {@code self}'s twin, written by {@code write}, whose answer is a color, asked at once
     * with {@code frame} on {@code frames} while it runs (the worker's callbacks during the call find it
     * there): the color, or what the student's code threw, rethrown.
     */
    private static <F> Vec3 colorCall(Object self, Deque<F> frames, F frame, java.util.function.Consumer<JudgeObjects.Message> write) {
        frames.addLast(frame);
        Outcome outcome;
        try {
            outcome = Worker.get().call(write, in -> returnedOrThrew(in, WireIn::vec));
        } finally {
            frames.removeLast();
        }
        outcome.rethrow(self);
        return (Vec3) outcome.value;
    }

    /** An answer that is a value ({@code value} reads it) or what the student's code threw. */
    private static Outcome returnedOrThrew(WireIn in, java.util.function.Function<WireIn, Object> value) {
        int status = in.u8();
        if (status == Protocol.THREW) {
            return Outcome.threw(ThrownData.read(in));
        }
        expect(status);
        return Outcome.value(value.apply(in));
    }

    private static void expect(int status) {
        if (status != Protocol.RETURNED) {
            throw new WireError("an answer of status " + status);
        }
    }

    /** An answer as read: returned (with what changed) or threw. */
    static final class Outcome {
        final boolean hit;
        final int mask;
        final int rayMask;
        final Object value;
        final ThrownData thrown;

        private Outcome(boolean hit, int mask, int rayMask, Object value, ThrownData thrown) {
            this.hit = hit;
            this.mask = mask;
            this.rayMask = rayMask;
            this.value = value;
            this.thrown = thrown;
        }

        static Outcome intersected(boolean hit, int mask, int rayMask) {
            return new Outcome(hit, mask, rayMask, null, null);
        }

        static Outcome value(Object value) {
            return new Outcome(false, 0, 0, value, null);
        }

        static Outcome threw(ThrownData thrown) {
            return new Outcome(false, 0, 0, null, thrown);
        }

        /** Throws what the student's code threw, if it did. */
        void rethrow(Object self) {
            if (thrown != null) {
                throw Rethrown.sneaky(Rethrown.of(thrown, self.getClass()));
            }
        }
    }
}
