package ray.grading.judge;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import ray.IntersectionRecord;
import ray.Ray;
import ray.grading.wire.Answer;
import ray.grading.wire.Batches;
import ray.grading.wire.Protocol;
import ray.grading.wire.Records;
import ray.grading.wire.ThrownData;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;
import ray.math.Vec3;
import ray.render.AnswerRounds;
import ray.surface.Surface;

/**
 * The judge's {@link AnswerRounds}: inside a computation (a pixel, a test's block), a stand-in's call
 * is answered from what the worker said in earlier rounds, or guessed (a miss, a plain ray, black)
 * and noted; at the round's end the noted questions go to the worker as one batch, with the
 * judge-side answers the student's code needed last time; the answers are kept until the
 * computations are done ({@link #forgetAnswers}). Outside a computation a stand-in asks at once.
 */
final class Rounds extends AnswerRounds {
    private static final Rounds INSTANCE = new Rounds();
    /** A batch message stays below this size; more questions go in another message. */
    private static final int BATCH_BYTES = 24 << 20;

    /** This thread's computation: how deeply nested, and whether it guessed. */
    private static final class Computation {
        int depth;
        boolean guessed;
    }

    private final ThreadLocal<Computation> computation = ThreadLocal.withInitial(Computation::new);
    private final IntersectAnswers intersects = new IntersectAnswers();
    private final Map<Questions.UvKey, Object> cameraAnswers = new HashMap<>();
    private final Map<Questions.UvKey, Object> textureAnswers = new HashMap<>();
    private volatile Questions questions = new Questions();
    /** Judge-side answers the worker said it needs: certified surfaces' rays, and exact questions. */
    private final Map<JudgeRay, Boolean> neededBases = new LinkedHashMap<>();
    private final List<ExactQuestion> neededExact = new ArrayList<>();

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
        return INSTANCE.computation.get().depth > 0 ? INSTANCE : null;
    }

    @Override
    protected void beginComputation() {
        Computation c = computation.get();
        if (c.depth++ == 0) {
            c.guessed = false;
        }
    }

    @Override
    protected boolean endComputation() {
        Computation c = computation.get();
        c.depth--;
        return !c.guessed;
    }

    private void guessed() {
        computation.get().guessed = true;
    }

    boolean intersect(StandIn self, IntersectionRecord out, Ray ray) {
        RayKey key = RayKey.of(ray);
        if (key == null) {
            // A ray without an origin or direction: nothing to key it by; asked at once.
            return StudentCalls.intersectNow((Surface) self, out, ray);
        }
        Answer answer = intersects.lookup(self, key, ray.end, out);
        if (answer == null) {
            questions.intersect(self, key, ray.end, out);
            guessed();
            return false;
        }
        if (answer.status == Protocol.THREW) {
            throw Rethrown.sneaky(Rethrown.of(answer.thrown, self.getClass()));
        }
        return answer.applyTo(out, ray);
    }

    Ray generateRay(StandIn self, double u, double v) {
        Questions.UvKey key = new Questions.UvKey(self, u, v);
        Object answer = cameraAnswers.get(key);
        if (answer == null) {
            questions.cameraCalls.put(key, self);
            guessed();
            return new Ray(Vec3.ZERO, new Vec3(0, 0, -1));
        }
        if (answer instanceof ThrownData) {
            throw Rethrown.sneaky(Rethrown.of((ThrownData) answer, self.getClass()));
        }
        // A fresh ray each time: the caller may shorten it.
        return answer == NULL ? null : ((Ray) answer).copy();
    }

    Vec3 texColor(StandIn self, double u, double v) {
        Questions.UvKey key = new Questions.UvKey(self, u, v);
        Object answer = textureAnswers.get(key);
        if (answer == null) {
            questions.textureCalls.put(key, self);
            guessed();
            return Vec3.ZERO;
        }
        if (answer instanceof ThrownData) {
            throw Rethrown.sneaky(Rethrown.of((ThrownData) answer, self.getClass()));
        }
        return answer == NULL ? null : (Vec3) answer;
    }

    /** A null the student's method returned, as kept. */
    private static final Object NULL = new Object();

    @Override
    protected void forgetAnswers() {
        intersects.clear();
        cameraAnswers.clear();
        textureAnswers.clear();
        questions = new Questions();
        neededBases.clear();
        neededExact.clear();
    }

    @Override
    protected boolean fetchGuessed() {
        // Exact judge-side questions first: answering them may ask the worker more (a judge-side
        // surface holding a student's object), which then goes in this round's batch.
        List<ExactQuestion> exactTable = new ArrayList<>();
        for (ExactQuestion q : new ArrayList<>(neededExact)) {
            if (q.answer()) {
                exactTable.add(q);
                neededExact.remove(q);
            }
        }
        Questions asked = questions;
        questions = new Questions();
        if (asked.isEmpty() && neededBases.isEmpty() && exactTable.isEmpty()) {
            return false;
        }
        Map<JudgeRay, Answer> baseTable = new LinkedHashMap<>();
        for (JudgeRay r : neededBases.keySet()) {
            baseTable.put(r, r.baseAnswer());
        }
        neededBases.clear();
        long t0 = System.nanoTime();
        new Batch(asked, baseTable, exactTable).send(Worker.get());
        if (Boolean.getBoolean("ray1.debugRounds")) {
            System.err.printf("round: %d rays, %d camera, %d texture, %d bases, %d exact: %.3f s%n", asked.intersects.size(),
                    asked.cameraCalls.size(), asked.textureCalls.size(), baseTable.size(), exactTable.size(), (System.nanoTime() - t0) / 1e9);
        }
        return true;
    }

    /** One round's questions, sent in as many messages as their size needs, and their answers kept. */
    private final class Batch {
        final List<Map.Entry<RayKey, Questions.PerRay>> rays;
        final List<Map.Entry<Questions.UvKey, StandIn>> cameraCalls;
        final List<Map.Entry<Questions.UvKey, StandIn>> textureCalls;
        final Map<JudgeRay, Answer> baseTable;
        final List<ExactQuestion> exactTable;

        Batch(Questions asked, Map<JudgeRay, Answer> baseTable, List<ExactQuestion> exactTable) {
            this.rays = new ArrayList<>(asked.intersects.entrySet());
            this.cameraCalls = new ArrayList<>(asked.cameraCalls.entrySet());
            this.textureCalls = new ArrayList<>(asked.textureCalls.entrySet());
            this.baseTable = baseTable;
            this.exactTable = exactTable;
        }

        void send(Worker worker) {
            int ray = 0;
            int camera = 0;
            int texture = 0;
            boolean tablesSent = false;
            while (!tablesSent || ray < rays.size() || camera < cameraCalls.size() || texture < textureCalls.size()) {
                int[] next = new int[3];
                int rayFrom = ray;
                int cameraFrom = camera;
                int textureFrom = texture;
                worker.batch(m -> {
                    next[0] = writeRays(m, rayFrom);
                    next[1] = writeCalls(m, cameraCalls, cameraFrom);
                    next[2] = writeCalls(m, textureCalls, textureFrom);
                    writeTables(m, rayFrom == 0 && cameraFrom == 0 && textureFrom == 0);
                }, in -> {
                    readRays(in, rayFrom, next[0]);
                    readCalls(in, cameraCalls, cameraFrom, next[1], cameraAnswers, true);
                    readCalls(in, textureCalls, textureFrom, next[2], textureAnswers, false);
                    readNeeds(in, worker);
                    return null;
                });
                ray = next[0];
                camera = next[1];
                texture = next[2];
                tablesSent = true;
            }
        }

        /** Writes rays from {@code from} while the message is small enough; returns where it stopped. */
        private int writeRays(JudgeObjects.Message m, int from) {
            WireOut body = m.body;
            int countAt = body.size();
            body.i32(0);
            int k = from;
            for (; k < rays.size() && (k == from || body.size() < BATCH_BYTES); k++) {
                RayKey key = rays.get(k).getKey();
                Questions.PerRay asked = rays.get(k).getValue();
                body.f64(Double.longBitsToDouble(key.ox)).f64(Double.longBitsToDouble(key.oy)).f64(Double.longBitsToDouble(key.oz))
                        .f64(Double.longBitsToDouble(key.dx)).f64(Double.longBitsToDouble(key.dy)).f64(Double.longBitsToDouble(key.dz))
                        .f64(key.startValue());
                int candidates = Math.min(asked.ends.size(), Batches.MAX_CANDIDATES);
                body.i32(candidates);
                for (int c = 0; c < candidates; c++) {
                    body.f64(asked.ends.get(c));
                    Records.write(body, asked.befores.get(c), m);
                }
                body.i32(asked.targets.size());
                for (StandIn target : asked.targets) {
                    m.target(target);
                }
            }
            body.patchI32(countAt, k - from);
            return k;
        }

        private int writeCalls(JudgeObjects.Message m, List<Map.Entry<Questions.UvKey, StandIn>> calls, int from) {
            WireOut body = m.body;
            int countAt = body.size();
            body.i32(0);
            int k = from;
            for (; k < calls.size() && (k == from || body.size() < BATCH_BYTES); k++) {
                m.target(calls.get(k).getValue());
                body.f64(calls.get(k).getKey().uValue()).f64(calls.get(k).getKey().vValue());
            }
            body.patchI32(countAt, k - from);
            return k;
        }

        private void writeTables(JudgeObjects.Message m, boolean first) {
            WireOut body = m.body;
            body.i32(first ? baseTable.size() : 0);
            if (first) {
                for (Map.Entry<JudgeRay, Answer> e : baseTable.entrySet()) {
                    body.i32(m.judgeHandle(e.getKey().surface));
                    e.getKey().writeKey(body);
                    e.getValue().write(body, m);
                }
            }
            body.i32(first ? exactTable.size() : 0);
            if (first) {
                for (ExactQuestion q : exactTable) {
                    body.i32(m.judgeHandle(q.surface));
                    Records.writeRay(body, q.ray);
                    Records.write(body, q.before, m);
                    q.answer.write(body, m);
                }
            }
        }

        private void readRays(WireIn in, int from, int to) {
            JudgeObjects objects = Worker.get().objects();
            for (int k = from; k < to; k++) {
                RayKey key = rays.get(k).getKey();
                Questions.PerRay asked = rays.get(k).getValue();
                IntersectAnswers.PerRay known = intersects.ray(key);
                List<Integer> index = new ArrayList<>();
                int candidates = Math.min(asked.ends.size(), Batches.MAX_CANDIDATES);
                for (int c = 0; c < candidates; c++) {
                    index.add(known.add(asked.ends.get(c), asked.befores.get(c)));
                }
                int extra = in.count(Batches.MAX_CANDIDATES, "added candidates");
                List<Double> ends = new ArrayList<>(asked.ends.subList(0, candidates));
                for (int e = 0; e < extra; e++) {
                    double end = in.f64();
                    IntersectionRecord before = new IntersectionRecord();
                    Records.read(in, before, objects.reader());
                    index.add(known.add(end, before));
                    ends.add(end);
                }
                for (StandIn target : asked.targets) {
                    int base = in.i32();
                    if (base < -1 || base >= index.size()) {
                        throw new ray.grading.wire.WireError("a base answer of candidate " + base);
                    }
                    Answer baseAnswer = base < 0 ? null : Answer.read(in, objects.reader());
                    Answer[] byCandidate = new Answer[index.size()];
                    if (baseAnswer != null) {
                        for (int c = 0; c < byCandidate.length; c++) {
                            byCandidate[c] = baseAnswer.predict(key.startValue(), ends.get(c));
                        }
                    }
                    int explicit = in.count(index.size(), "explicit answers");
                    for (int e = 0; e < explicit; e++) {
                        int c = in.index(index.size(), "candidate");
                        int kind = in.u8();
                        if (kind == Batches.NEEDS) {
                            byCandidate[c] = null;
                        } else if (kind == Batches.ANSWERED) {
                            byCandidate[c] = Answer.read(in, objects.reader());
                        } else {
                            throw new ray.grading.wire.WireError("an answer of kind " + kind);
                        }
                    }
                    for (int c = 0; c < byCandidate.length; c++) {
                        if (byCandidate[c] != null) {
                            known.put(target, index.get(c), byCandidate[c]);
                        }
                    }
                }
            }
        }

        private void readCalls(WireIn in, List<Map.Entry<Questions.UvKey, StandIn>> calls, int from, int to,
                Map<Questions.UvKey, Object> answers, boolean camera) {
            for (int k = from; k < to; k++) {
                int status = in.u8();
                Object answer;
                if (status == Protocol.THREW) {
                    answer = ThrownData.read(in);
                } else if (status == Protocol.RETURNED) {
                    Object value = camera ? Records.readRayOrNull(in) : in.vec();
                    answer = value == null ? NULL : value;
                } else {
                    throw new ray.grading.wire.WireError("an answer of status " + status);
                }
                answers.put(calls.get(k).getKey(), answer);
            }
        }

        private void readNeeds(WireIn in, Worker worker) {
            JudgeObjects objects = worker.objects();
            int bases = in.count(Protocol.MAX_ENTRIES, "needed base answers");
            for (int k = 0; k < bases; k++) {
                Surface surface = objects.readJudgeSurface(in.i32());
                RayKey key = RayKey.of(in.f64(), in.f64(), in.f64(), in.f64(), in.f64(), in.f64(), in.f64());
                neededBases.put(new JudgeRay(surface, key), true);
            }
            int exact = in.count(Protocol.MAX_ENTRIES, "needed exact answers");
            for (int k = 0; k < exact; k++) {
                Surface surface = objects.readJudgeSurface(in.i32());
                Ray ray = Records.readRay(in);
                IntersectionRecord before = new IntersectionRecord();
                Records.read(in, before, objects.reader());
                neededExact.add(new ExactQuestion(surface, ray, before));
            }
        }
    }

    /** A certified judge-side surface and a ray, whose endless answer the worker derives the others from. */
    private static final class JudgeRay {
        final Surface surface;
        final RayKey key;

        JudgeRay(Surface surface, RayKey key) {
            this.surface = surface;
            this.key = key;
        }

        void writeKey(WireOut out) {
            out.f64(Double.longBitsToDouble(key.ox)).f64(Double.longBitsToDouble(key.oy)).f64(Double.longBitsToDouble(key.oz))
                    .f64(Double.longBitsToDouble(key.dx)).f64(Double.longBitsToDouble(key.dy)).f64(Double.longBitsToDouble(key.dz))
                    .f64(key.startValue());
        }

        /** The surface's answer to the ray with an endless segment, on a record of sentinels (so that every field it writes shows). */
        Answer baseAnswer() {
            IntersectionRecord before = Sentinels.record();
            IntersectionRecord out = new IntersectionRecord();
            out.set(before);
            Ray ray = key.ray(Double.POSITIVE_INFINITY);
            try {
                boolean hit = surface.intersect(out, ray);
                return Answer.returned(hit, before, out, ray.start, Double.POSITIVE_INFINITY, ray);
            } catch (RuntimeException | Error e) {
                return Answer.threw(ThrownData.of(e, "ray.grading."));
            }
        }

        @Override
        public int hashCode() {
            return System.identityHashCode(surface) * 31 + key.hashCode();
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof JudgeRay && ((JudgeRay) o).surface == surface && ((JudgeRay) o).key.equals(key);
        }
    }

    /** A judge-side surface the worker asked about exactly: answered here as a computation of its own. */
    private final class ExactQuestion {
        final Surface surface;
        final Ray ray;
        final IntersectionRecord before;
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
            beginComputation();
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
            if (!endComputation()) {
                return false;
            }
            answer = a;
            return true;
        }
    }
}
