package ray.grading.judge;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import ray.AnswerRounds;
import ray.IntersectionRecord;
import ray.Ray;
import ray.grading.wire.Answer;
import ray.grading.wire.Protocol;
import ray.grading.wire.ThrownData;
import ray.math.Vec3;
import ray.surface.Surface;
import ray.surface.Triangle;
import ray.surface.TriangleSet;

/**
 * The judge's {@link AnswerRounds}. Inside a computation (a pixel, a test's block), a stand-in's call
 * is answered from the computation's log ({@link Computation}), or guessed (a miss, a plain ray,
 * black) and noted; at the round's end the noted questions of every computation go to the worker
 * together ({@link RoundBatch}), with the judge-side answers the student's code needed last time, and
 * each answer is put into the question that asked it. Outside a computation a stand-in asks at once.
 */
final class Rounds extends AnswerRounds {
    private static final Rounds INSTANCE = new Rounds();

    /** This thread's computations, the innermost last (a judge-side question is answered as a computation of its own). */
    private final ThreadLocal<Deque<Computation>> running = ThreadLocal.withInitial(ArrayDeque::new);
    /** Computations that asked questions not sent yet. */
    private final Queue<Computation> asking = new ConcurrentLinkedQueue<>();
    /** Judge-side answers the worker said it needs: certified surfaces' rays, and exact questions. */
    final Map<RoundBatch.JudgeRay, Boolean> neededBases = new LinkedHashMap<>();
    final List<ExactQuestion> neededExact = new ArrayList<>();

    private Rounds() {
    }

    /** Makes answers come in rounds in this judge (when the grader set up a worker). */
    static void installIfGrading() {
        if (System.getProperty(Judge.WORKER_PROPERTY) != null) {
            AnswerRounds.install(INSTANCE);
        }
    }

    /** The rounds, when this thread is inside a computation; null when a call must be asked at once. */
    static Rounds deferring() {
        return INSTANCE.running.get().isEmpty() ? null : INSTANCE;
    }

    @Override
    protected void beginComputation(Object state) {
        Computation c = state instanceof Computation ? (Computation) state : new Computation();
        c.begin();
        running.get().addLast(c);
    }

    @Override
    protected Object endComputation() {
        Computation c = running.get().removeLast();
        c.end();
        if (c.asking) {
            asking.add(c);
        }
        return c.guessed ? c : null;
    }

    private Computation current() {
        return running.get().getLast();
    }

    /** An intersect of a stand-in, or of a set of stand-in triangles searched as a whole. */
    boolean intersect(Object self, IntersectionRecord out, Ray ray) {
        if (ray.origin == null || ray.direction == null) {
            // A ray without an origin or direction: asked at once (a whole set, triangle by triangle).
            return self instanceof StandIn ? StudentCalls.intersectNow((Surface) self, out, ray) : ((WholeSearch) self).copy.intersect(out, ray);
        }
        // A surface searched as a whole is asked as the original: every thread's copy of it asks the same question.
        Object target = self instanceof WholeSearch ? ((WholeSearch) self).original : self;
        Computation c = current();
        Question q = c.intersect(target, ray, out);
        if (q.answer == null) {
            c.unknown(q);
            return false;
        }
        Answer answer = (Answer) q.answer;
        if (answer.status == Protocol.THREW) {
            throw Rethrown.sneaky(Rethrown.of(answer.thrown, self.getClass()));
        }
        return answer.applyTo(out, ray);
    }

    /** Whether anything of a set searched as a whole lies on the ray's segment. */
    boolean anyHit(WholeSearch self, Ray ray) {
        if (ray.origin == null || ray.direction == null) {
            return self.copy.intersectsAny(ray);
        }
        Computation c = current();
        Question q = c.anyHit(self.original, ray);
        if (q.answer == null) {
            c.unknown(q);
            return false;
        }
        if (q.answer instanceof ThrownData) {
            throw Rethrown.sneaky(Rethrown.of((ThrownData) q.answer, WholeSearch.class));
        }
        return (Boolean) q.answer;
    }

    Ray generateRay(StandIn self, double u, double v) {
        Object answer = uv(Question.Kind.CAMERA, self, u, v);
        if (answer == null) {
            return new Ray(Vec3.ZERO, new Vec3(0, 0, -1));
        }
        // A fresh ray each time: the caller may shorten it.
        return answer == Question.NULL ? null : ((Ray) answer).copy();
    }

    Vec3 texColor(StandIn self, double u, double v) {
        Object answer = uv(Question.Kind.TEXTURE, self, u, v);
        if (answer == null) {
            return Vec3.ZERO;
        }
        return answer == Question.NULL ? null : (Vec3) answer;
    }

    /** A camera's or texture's answer, or null (a guess); throws what the student's code threw. */
    private Object uv(Question.Kind kind, StandIn self, double u, double v) {
        Computation c = current();
        Question q = c.uv(kind, self, u, v);
        if (q.answer == null) {
            c.unknown(q);
            return null;
        }
        if (q.answer instanceof ThrownData) {
            throw Rethrown.sneaky(Rethrown.of((ThrownData) q.answer, self.getClass()));
        }
        return q.answer;
    }

    /**
     * A set of triangles that are all of the class graded now, searched by its tree (the framework's
     * default), and a placement of such a set, while answers come in rounds: searched as a whole where
     * the student's Triangle runs, the placement's world ray asked as the other surfaces' are.
     */
    @Override
    protected Surface searchedAsWhole(Surface original, boolean accelerated, Surface copy) {
        if (!accelerated) {
            return copy;
        }
        if (original instanceof TriangleSet) {
            TriangleSet set = (TriangleSet) original;
            if (set.triangleCount() == 0) {
                return copy;
            }
            for (Triangle t : set.triangles()) {
                if (!StudentCalls.isRemote(t)) {
                    return copy;
                }
            }
            return new WholeSearch(original, copy);
        }
        if (original instanceof ray.surface.Transformed && copy instanceof ray.surface.Transformed
                && ((ray.surface.Transformed) copy).placed() instanceof WholeSearch) {
            return new WholeSearch(original, copy);
        }
        return copy;
    }

    @Override
    protected void forgetAnswers() {
        Worker.get().objects().certification().forget();
        asking.clear();
        neededBases.clear();
        neededExact.clear();
        // Answers still on their way (a render that threw) are read and dropped: the next batch's must come next.
        try {
            while (!unanswered.isEmpty()) {
                unanswered.poll().await(Worker.get());
            }
        } catch (WorkerFailure e) {
            unanswered.clear();
        }
    }

    /** Batches asked and not yet awaited, oldest first. */
    private final Queue<RoundBatch> unanswered = new java.util.ArrayDeque<>();

    @Override
    protected Object askGuessed() {
        // Exact judge-side questions first: answering one may ask the worker more (a judge-side surface
        // holding a student's object), which then goes in this round's batch.
        List<ExactQuestion> exactTable = new ArrayList<>();
        for (ExactQuestion q : new ArrayList<>(neededExact)) {
            if (q.answer()) {
                exactTable.add(q);
                neededExact.remove(q);
            }
        }
        List<Computation> computations = new ArrayList<>(asking);
        asking.clear();
        RoundBatch batch = new RoundBatch(this, computations, exactTable);
        if (batch.isEmpty()) {
            return null;
        }
        batch.ask(Worker.get());
        unanswered.add(batch);
        return batch;
    }

    @Override
    protected void awaitAnswers(Object asked) {
        while (!unanswered.isEmpty()) {
            RoundBatch batch = unanswered.poll();
            batch.await(Worker.get());
            if (batch == asked) {
                return;
            }
        }
    }

    /**
     * A set of triangles of the class graded now, or a placement of one, in a render's search: searched
     * as a whole in the worker while answers come in rounds, and by its copy otherwise.
     */
    static final class WholeSearch extends Surface {
        final Surface original;
        final Surface copy;

        WholeSearch(Surface original, Surface copy) {
            this.original = original;
            this.copy = copy;
            setShader(copy.getShader());
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            Rounds rounds = deferring();
            return rounds != null ? rounds.intersect(this, out, ray) : copy.intersect(out, ray);
        }

        @Override
        public boolean intersectsAny(Ray ray) {
            Rounds rounds = deferring();
            return rounds != null ? rounds.anyHit(this, ray) : copy.intersectsAny(ray);
        }

        @Override
        public ray.math.Bounds bounds() {
            return copy.bounds();
        }

        @Override
        public List<Surface> children() {
            return copy.children();
        }

        @Override
        public String toString() {
            return copy.toString();
        }
    }

    /** A judge-side surface the worker asked about exactly: answered here as a computation of its own. */
    final class ExactQuestion {
        final Surface surface;
        final Ray ray;
        final IntersectionRecord before;
        private Object state;
        Answer answer;

        ExactQuestion(Surface surface, Ray ray, IntersectionRecord before) {
            this.surface = surface;
            this.ray = ray;
            this.before = before;
        }

        /** Answers it, unless that needed a guess (then it is asked again next round); whether it was answered. */
        boolean answer() {
            IntersectionRecord out = new IntersectionRecord();
            out.set(before);
            Ray asked = ray.copy();
            beginComputation(state);
            Answer a;
            try {
                boolean hit = surface.intersect(out, asked);
                a = Answer.returned(hit, before, out, ray.start, ray.end, asked);
            } catch (WorkerFailure e) {
                endComputation();
                throw e;
            } catch (RuntimeException | Error e) {
                a = Answer.threw(ThrownData.of(e, "ray.grading."));
            }
            state = endComputation();
            if (state != null) {
                return false;
            }
            answer = a;
            return true;
        }
    }
}
