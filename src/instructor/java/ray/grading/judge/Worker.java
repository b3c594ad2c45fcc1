package ray.grading.judge;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Function;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Hittable;
import ray.grading.wire.Frames;
import ray.grading.wire.Protocol;
import ray.grading.wire.Records;
import ray.grading.wire.ThrownData;
import ray.grading.wire.Trees;
import ray.grading.wire.WireError;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;
import ray.math.Vec3;
import ray.shading.BrdfShader;
import ray.surface.Surface;

/**
 * The judge's worker: started when a stand-in first needs it, as the grader's {@link Containment}
 * says, and asked one call at a time. While a call runs, the student's code may call back a
 * judge-side surface (a group's child), which this class runs and answers. Anything a worker does
 * wrong (ending, stalling, answering out of format) ends it, and the next call starts a fresh one;
 * its objects are then sent anew.
 */
final class Worker {
    /** Seconds any one call may take at most, whatever else limits it (a test's own limit interrupts sooner). */
    static final long CALL_LIMIT_SECONDS = 120;
    /** Seconds a worker may take to start. */
    private static final long START_LIMIT_SECONDS = 60;

    private static Worker current;
    /** The task whose worker runs (its classes are the student's there), from {@link StudentCalls#grade}. */
    private static int task;

    private final Containment containment;
    private final JudgeObjects objects = new JudgeObjects(new Certification());
    /** The running worker; read without the lock only to kill it ({@link #kill}). */
    private volatile WorkerProcess process;

    private Worker(Containment containment) {
        this.containment = containment;
    }

    /**
     * The worker of the task graded now, as the grader set it up: the file {@code task-N} in the folder
     * {@link Judge#WORKER_PROPERTY} names.
     */
    static synchronized Worker get() {
        if (current == null) {
            String setup = System.getProperty(Judge.WORKER_PROPERTY);
            if (setup == null) {
                throw new IllegalStateException("a student class was called, but no worker is set up (" + Judge.WORKER_PROPERTY + ")");
            }
            try {
                current = new Worker(Containment.read(Path.of(setup).resolve("task-" + task)));
            } catch (IOException e) {
                throw new IllegalStateException("cannot read the worker's setup: " + e.getMessage(), e);
            }
        }
        return current;
    }

    /** Another task is graded: its own worker (with its own classes) starts when first asked; the last one ends. */
    static synchronized void taskChanged(int newTask) {
        if (current != null) {
            // Killed first: a test abandoned at its time limit may still wait for the worker, holding its lock.
            current.kill();
            current.end();
            current = null;
        }
        task = newTask;
    }

    /** For the grader's own tests: a worker started by {@code containment}. */
    static synchronized void use(Containment containment) {
        if (current != null) {
            current.end();
        }
        current = new Worker(containment);
    }

    /** Ends the worker, if this judge ever started one. */
    static synchronized void stopIfStarted() {
        if (current != null) {
            current.kill();
            current.end();
        }
    }

    /** Stops the running worker's process at once, without the lock a waiting call holds; that call then fails. */
    private void kill() {
        WorkerProcess running = process;
        if (running != null) {
            running.kill();
        }
    }

    JudgeObjects objects() {
        return objects;
    }

    /** When the present call must be answered by (System.nanoTime). */
    private static long callDeadline() {
        long limit = System.nanoTime() + TimeUnit.SECONDS.toNanos(CALL_LIMIT_SECONDS);
        String gradeEnds = System.getProperty(Judge.DEADLINE_PROPERTY);
        if (gradeEnds != null) {
            long left = Long.parseLong(gradeEnds) - System.currentTimeMillis();
            limit = Math.min(limit, System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(Math.max(0, left)));
        }
        return limit;
    }

    private void ensureStarted() {
        if (process == null || !process.alive()) {
            if (process != null) {
                end();
            }
            long deadline = Math.min(callDeadline(), System.nanoTime() + TimeUnit.SECONDS.toNanos(START_LIMIT_SECONDS));
            process = WorkerProcess.start(containment.command(), containment, deadline);
        }
    }

    /**
     * One call: {@code write} writes it (its definitions come along), {@code read} reads the answer
     * whole. Whatever goes wrong on the worker's side is a {@link WorkerFailure}, after which the
     * worker is gone.
     */
    synchronized <T> T call(Consumer<JudgeObjects.Message> write, Function<WireIn, T> read) {
        ensureStarted();
        return answered(() -> {
            JudgeObjects.Message message = objects.new Message();
            write.accept(message);
            process.send(Protocol.CALL, message.assembled());
            return await(Protocol.ANSWER);
        }, read);
    }

    /** An answer the worker owes, as {@code read} reads it whole; whatever goes wrong ends the worker and is a {@link WorkerFailure}. */
    private <T> T answered(Answering answering, Function<WireIn, T> read) {
        try {
            WireIn answer = answering.answer();
            T result = read.apply(answer);
            answer.end();
            return result;
        } catch (WorkerFailure e) {
            end();
            throw e;
        } catch (WireError e) {
            end();
            throw new WorkerFailure("the worker answered out of format (" + e.getMessage() + ")");
        } catch (InterruptedException e) {
            end();
            Thread.currentThread().interrupt();
            throw new WorkerFailure(WorkerFailure.Kind.TIMED_OUT, "interrupted while your code ran (the test's time limit)");
        }
    }

    /** Waits for an answer. */
    private interface Answering {
        WireIn answer() throws InterruptedException;
    }

    /**
     * Sends batches ({@link RoundBatch}) without waiting: a thread of their own writes them, so that the
     * judge renders other pixels while the worker answers. Their answers come in order ({@link #nextBatchAnswer}).
     */
    synchronized Object sendBatches(List<WireOut> messages) {
        ensureStarted();
        for (WireOut message : messages) {
            process.send(Protocol.BATCH, message);
        }
        return process;
    }

    /**
     * The answer to the oldest batch sent (to {@code sentTo}, what {@link #sendBatches} returned) and not yet
     * answered, read whole by the caller; a failure ends the worker.
     */
    synchronized <T> T nextBatchAnswer(Object sentTo, Function<WireIn, T> read) {
        if (process == null || process != sentTo) {
            throw new WorkerFailure(WorkerFailure.Kind.ENDED, "the JVM running your code ended before it answered");
        }
        return answered(() -> {
            Frames.Frame frame = process.next(callDeadline());
            if (frame.type != Protocol.BATCH_ANSWER) {
                throw new WorkerFailure("the worker sent a message of type " + frame.type + " for a batch");
            }
            return frame.reader();
        }, read);
    }

    /** The worker's message of {@code type}, serving its callbacks until it comes. */
    private WireIn await(int type) throws InterruptedException {
        long deadline = callDeadline();
        while (true) {
            Frames.Frame frame = process.next(deadline);
            if (frame.type == type) {
                return frame.reader();
            }
            if (frame.type != Protocol.CALLBACK) {
                throw new WorkerFailure("the worker sent a message of type " + frame.type + " out of turn");
            }
            serveCallback(frame.reader());
        }
    }

    /** Answers what the student's code asked of the judge's side during a call: a surface's intersect, or a shading context's. */
    private void serveCallback(WireIn in) {
        int kind = in.u8();
        switch (kind) {
            case Protocol.CB_INTERSECT:
                serveIntersect(in);
                break;
            case Protocol.CB_UNOCCLUDED:
            case Protocol.CB_RADIANCE:
                serveShading(kind, in);
                break;
            case Protocol.CB_SHADE_HIT:
                serveShadeHit(in);
                break;
            case Protocol.CB_BRDF:
                serveBrdf(in);
                break;
            case Protocol.CB_PRIMITIVE:
                servePrimitive(in);
                break;
            default:
                throw new WireError("a callback of kind " + kind);
        }
    }

    /**
     * Runs the shadow test or traces the mirror ray that the student's shade asked its context for,
     * with the context of the shade call running ({@link StudentCalls#shading}), and sends back the
     * answer. A hit the student's code passes is the one the call gave when the worker says so (then
     * the judge's own record, with whatever the student's code changed in it), null, or a record of its own.
     */
    void serveShading(int kind, WireIn in) {
        StudentCalls.ShadeCall call = StudentCalls.shading();
        if (call == null) {
            throw new WireError("a shading callback outside a shade call");
        }
        int which = in.u8();
        IntersectionRecord hit;
        if (which == Protocol.HIT_NULL) {
            hit = null;
        } else if (which == Protocol.HIT_GIVEN || which == Protocol.HIT_OTHER) {
            hit = which == Protocol.HIT_GIVEN ? call.hit : new IntersectionRecord();
            Records.read(in, hit, objects.reader());
        } else {
            throw new WireError("a shading callback's hit of kind " + which);
        }
        Vec3 vector = in.vec();
        int depth = kind == Protocol.CB_RADIANCE ? in.i32() : 0;
        in.end();
        boolean unoccluded = false;
        Vec3 radiance = null;
        try {
            if (kind == Protocol.CB_UNOCCLUDED) {
                unoccluded = call.context.unoccluded(hit, vector);
            } else {
                radiance = call.context.radiance(hit, vector, depth);
            }
        } catch (WorkerFailure e) {
            throw e;
        } catch (Throwable t) { // the judge's context threw: it goes back through the student's code
            sendThrown(t);
            return;
        }
        JudgeObjects.Message reply = objects.new Message();
        reply.body.u8(Protocol.RETURNED);
        if (kind == Protocol.CB_UNOCCLUDED) {
            reply.body.bool(unoccluded);
        } else {
            reply.body.vec(radiance);
        }
        process.send(Protocol.CALLBACK_ANSWER, reply.assembled());
    }

    /**
     * Shades the hit the student's shadeRay asked to have shaded, with the stand-in's own shading (the
     * renderer's or the test's), and sends back the color.
     */
    void serveShadeHit(WireIn in) {
        ray.render.SceneTracer tracer = StudentCalls.tracing();
        if (tracer == null) {
            throw new WireError("a shading callback outside a shadeRay call");
        }
        IntersectionRecord hit = new IntersectionRecord();
        Records.read(in, hit, objects.reader());
        Ray ray = Records.readRay(in);
        int depth = in.i32();
        in.end();
        Vec3 color;
        try {
            color = tracer.shade(hit, ray, depth);
        } catch (WorkerFailure e) {
            throw e;
        } catch (Throwable t) { // the judge's shading threw: it goes back through the student's code
            sendThrown(t);
            return;
        }
        sendColor(color);
    }

    /** Evaluates the BRDF of the 2019 shader whose shade call is running, for the student's light loop, and sends back its value. */
    void serveBrdf(WireIn in) {
        StudentCalls.ShadeCall call = StudentCalls.shading();
        if (call == null || !(call.shader instanceof BrdfShader)) {
            throw new WireError("a BRDF callback outside a 2019 shader's shade call");
        }
        Vec3 rhoD = in.vec();
        Vec3 n = in.vec();
        Vec3 l = in.vec();
        Vec3 v = in.vec();
        in.end();
        Vec3 value;
        try {
            value = ((BrdfShader) call.shader).brdf().value(rhoD, n, l, v);
        } catch (WorkerFailure e) {
            throw e;
        } catch (Throwable t) { // the judge's BRDF threw (a null vector the student's code passed): back through its code
            sendThrown(t);
            return;
        }
        sendColor(value);
    }

    /** Answers a callback whose answer is a color. */
    private void sendColor(Vec3 color) {
        JudgeObjects.Message reply = objects.new Message();
        reply.body.u8(Protocol.RETURNED).vec(color);
        process.send(Protocol.CALLBACK_ANSWER, reply.assembled());
    }

    /** Runs the judge-side surface the student's code called and sends back what it did. */
    private void serveIntersect(WireIn in) {
        Surface target = objects.readJudgeSurface(in.i32());
        Ray ray = Records.readRay(in);
        IntersectionRecord record = new IntersectionRecord();
        Records.read(in, record, objects.reader());
        in.end();
        replyToTest(() -> target.intersect(record, ray), record, ray, true);
    }

    /**
     * Tests the primitive of a students' tree that the worker's copy of the tree asked about (the
     * stand-in's own primitive, by its place in the scene's order), counts the test as the stand-in's,
     * and sends back the answer: any hit, or the closest with what it changed of the record and the ray.
     */
    void servePrimitive(WireIn in) {
        ray.bvh.TreeData tree = objects.readTree(in.i32());
        Hittable primitive = Trees.primitive(tree, in.i32());
        Trees.addCounts(tree, 0, 1);
        boolean any = in.bool();
        Ray ray = Records.readRay(in);
        IntersectionRecord record = new IntersectionRecord();
        if (!any) {
            Records.read(in, record, objects.reader());
        }
        in.end();
        replyToTest(() -> any ? primitive.intersectsAny(ray) : primitive.intersect(record, ray), record, ray, !any);
    }

    /**
     * Runs a judge-side intersection test for the worker and answers with whether it hit and, with
     * {@code changes}, what it changed of the record and the ray; what it throws goes back through the
     * student's code.
     */
    private void replyToTest(java.util.function.BooleanSupplier test, IntersectionRecord record, Ray ray, boolean changes) {
        IntersectionRecord before = new IntersectionRecord();
        before.set(record);
        double start = ray.start;
        double end = ray.end;
        boolean hit;
        try {
            hit = test.getAsBoolean();
        } catch (WorkerFailure e) {
            throw e;
        } catch (Throwable t) { // a judge-side surface's exception goes back through the student's code
            sendThrown(t);
            return;
        }
        JudgeObjects.Message reply = objects.new Message();
        reply.body.u8(Protocol.RETURNED).bool(hit);
        if (changes) {
            Records.writeChanges(reply.body, Records.changes(before, record), record, reply);
            Records.writeRayChanges(reply.body, Records.rayChanges(start, end, ray), ray);
        }
        process.send(Protocol.CALLBACK_ANSWER, reply.assembled());
    }

    /** Answers a callback with what the judge's side threw, which goes back through the student's code. */
    private void sendThrown(Throwable t) {
        JudgeObjects.Message reply = objects.new Message();
        reply.body.u8(Protocol.THREW);
        ThrownData.of(t, "ray.grading.judge.").write(reply.body);
        process.send(Protocol.CALLBACK_ANSWER, reply.assembled());
    }

    /** Ends the worker and everything it started; the next call starts another. */
    synchronized void end() {
        if (process != null) {
            process.end();
            process = null;
        }
        objects.forget();
    }

    /** What the student's code printed in the running worker (the start of it). */
    synchronized String printed() {
        return process == null ? "" : process.printed();
    }
}
