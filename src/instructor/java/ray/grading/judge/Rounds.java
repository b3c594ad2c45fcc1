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
import ray.grading.wire.WireError;
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

    private IntersectAnswers.PerRay intersects(RayKey key) {
        return intersects.ray(key);
    }

    @Override
    protected void forgetAnswers() {
        Worker.get().objects().certification().forget();
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

    /**
     * One round's questions, sent in as many messages as their size needs, and their answers kept. With
     * each ray whose targets hold judge-side surfaces (a student's group and its children), the answers of
     * those the judge certified go along, for the ray as the group will pass it on ({@link #prefetch}).
     */
    private final class Batch {
        final List<Map.Entry<RayKey, Questions.PerRay>> intersects;
        final List<Map.Entry<Questions.UvKey, StandIn>> cameraCalls;
        final List<Map.Entry<Questions.UvKey, StandIn>> textureCalls;
        final Map<JudgeRay, Answer> baseTable;
        final List<ExactQuestion> exactTable;

        Batch(Questions asked, Map<JudgeRay, Answer> baseTable, List<ExactQuestion> exactTable) {
            this.intersects = new ArrayList<>(asked.intersects.entrySet());
            this.cameraCalls = new ArrayList<>(asked.cameraCalls.entrySet());
            this.textureCalls = new ArrayList<>(asked.textureCalls.entrySet());
            this.baseTable = baseTable;
            this.exactTable = exactTable;
        }

        void send(Worker worker) {
            int[] at = new int[3];
            boolean first = true;
            while (first || at[0] < intersects.size() || at[1] < cameraCalls.size() || at[2] < textureCalls.size()) {
                boolean withTables = first;
                int[] from = at.clone();
                int[] to = new int[3];
                worker.batch(m -> write(m, from, to, withTables), in -> {
                    read(in, worker, from, to);
                    return null;
                });
                at = to;
                first = false;
            }
        }

        /** One message: the rays it names, then each section, from {@code from}; {@code to} says where each section stopped. */
        private void write(JudgeObjects.Message m, int[] from, int[] to, boolean withTables) {
            Map<RayKey, Integer> rays = new LinkedHashMap<>();
            Map<Surface, List<Step>> plans = new java.util.IdentityHashMap<>();
            WireOut intersectSection = new WireOut();
            WireOut bases = new WireOut();
            int[] baseGroups = {0};
            intersectSection.i32(0);
            int k = from[0];
            for (; k < intersects.size() && (k == from[0] || intersectSection.size() + bases.size() < BATCH_BYTES); k++) {
                RayKey key = intersects.get(k).getKey();
                Questions.PerRay asked = intersects.get(k).getValue();
                int rayIndex = rays.computeIfAbsent(key, r -> rays.size());
                intersectSection.varint(rayIndex);
                int candidates = Math.min(asked.ends.size(), Batches.MAX_CANDIDATES);
                intersectSection.varint(candidates);
                for (int c = 0; c < candidates; c++) {
                    intersectSection.f64(asked.ends.get(c));
                    Records.write(intersectSection, asked.befores.get(c), m);
                }
                intersectSection.varint(asked.targets.size());
                for (StandIn target : asked.targets) {
                    intersectSection.varint(m.sync(target));
                    List<Step> plan = plans.computeIfAbsent((Surface) target, t -> planOf(t, m, 0));
                    if (!plan.isEmpty()) {
                        prefetch(plan, key.ray(Double.POSITIVE_INFINITY), rayIndex, rays, bases, baseGroups, m);
                    }
                }
            }
            intersectSection.patchI32(0, k - from[0]);
            to[0] = k;
            WireOut cameras = new WireOut();
            to[1] = writeCalls(m, cameras, cameraCalls, from[1]);
            WireOut textures = new WireOut();
            to[2] = writeCalls(m, textures, textureCalls, from[2]);
            if (withTables) {
                for (Map.Entry<JudgeRay, Answer> e : baseTable.entrySet()) {
                    bases.i32(rays.computeIfAbsent(e.getKey().key, r -> rays.size())).i32(1).i32(m.judgeHandle(e.getKey().surface));
                    e.getValue().write(bases, m);
                    baseGroups[0]++;
                }
            }
            WireOut exactSection = new WireOut();
            List<ExactQuestion> exact = withTables ? exactTable : List.of();
            exactSection.i32(exact.size());
            for (ExactQuestion q : exact) {
                RayKey key = RayKey.of(q.ray);
                exactSection.i32(m.judgeHandle(q.surface)).i32(rays.computeIfAbsent(key, r -> rays.size())).f64(q.ray.end);
                Records.write(exactSection, q.before, m);
                q.answer.write(exactSection, m);
            }
            WireOut body = m.body;
            body.i32(rays.size());
            for (RayKey key : rays.keySet()) {
                Records.writeKey(body, key.ray(Double.POSITIVE_INFINITY));
            }
            body.raw(intersectSection).raw(cameras).raw(textures).i32(baseGroups[0]).raw(bases).raw(exactSection);
        }

        /**
         * The answers of the certified judge-side surfaces that a target passes {@code ray} to, with an
         * endless segment, as one group of the base table: a student's group passes its children the ray
         * it was given, and a placement passes it in its own coordinates (a group of its own).
         */
        private void prefetch(List<Step> plan, Ray ray, int rayIndex, Map<RayKey, Integer> rays, WireOut bases, int[] groups,
                JudgeObjects.Message m) {
            int countAt = -1;
            int count = 0;
            for (Step step : plan) {
                if (step.placed != null) {
                    continue;
                }
                if (countAt < 0) {
                    bases.i32(rayIndex);
                    countAt = bases.size();
                    bases.i32(0);
                    groups[0]++;
                }
                bases.i32(step.handle);
                baseAnswer(step.surface, ray).write(bases, m);
                count++;
            }
            if (countAt >= 0) {
                bases.patchI32(countAt, count);
            }
            // Each placement's ray is a group of its own, after this one.
            for (Step step : plan) {
                if (step.placed != null) {
                    Ray local = step.placed.toLocal(ray);
                    if (local.origin != null && local.direction != null) {
                        prefetch(step.inner, local, rays.computeIfAbsent(RayKey.of(local), r -> rays.size()), rays, bases, groups, m);
                    }
                }
            }
        }

        /**
         * What a target passes a ray to, found once per batch: each certified judge-side surface among its
         * parts (through the parts of stand-ins it holds, a student's nested groups), and each placement of
         * a stand-in with the plan of what it places.
         */
        private List<Step> planOf(Surface target, JudgeObjects.Message m, int depth) {
            List<Step> plan = new ArrayList<>();
            if (depth > 32) {
                return plan;
            }
            Certification certification = Worker.get().objects().certification();
            for (Surface child : target.children()) {
                if (child instanceof StandIn) {
                    plan.addAll(planOf(child, m, depth + 1));
                } else if (child instanceof ray.surface.Transformed && certification.holdsStandIn(child)) {
                    ray.surface.Transformed placed = (ray.surface.Transformed) child;
                    List<Step> inner = placed.placed() instanceof StandIn ? planOf(placed.placed(), m, depth + 1) : List.of();
                    if (!inner.isEmpty()) {
                        plan.add(new Step(null, 0, placed, inner));
                    }
                } else if (certification.certified(child)) {
                    plan.add(new Step(child, m.judgeHandle(child), null, null));
                }
            }
            return plan;
        }

        private int writeCalls(JudgeObjects.Message m, WireOut section, List<Map.Entry<Questions.UvKey, StandIn>> calls, int from) {
            section.i32(0);
            int k = from;
            for (; k < calls.size() && (k == from || section.size() < BATCH_BYTES); k++) {
                section.u8(Protocol.REF_TWIN).i32(m.sync(calls.get(k).getValue()));
                section.f64(calls.get(k).getKey().uValue()).f64(calls.get(k).getKey().vValue());
            }
            section.patchI32(0, k - from);
            return k;
        }

        private void read(WireIn in, Worker worker, int[] from, int[] to) {
            JudgeObjects objects = worker.objects();
            for (int k = from[0]; k < to[0]; k++) {
                readRay(in, objects, intersects.get(k).getKey(), intersects.get(k).getValue());
            }
            readCalls(in, cameraCalls, from[1], to[1], cameraAnswers, true);
            readCalls(in, textureCalls, from[2], to[2], textureAnswers, false);
            readNeeds(in, objects);
        }

        private void readRay(WireIn in, JudgeObjects objects, RayKey key, Questions.PerRay asked) {
            IntersectAnswers.PerRay known = intersects(key);
            List<Integer> index = new ArrayList<>();
            List<Double> ends = new ArrayList<>();
            int candidates = Math.min(asked.ends.size(), Batches.MAX_CANDIDATES);
            for (int c = 0; c < candidates; c++) {
                index.add(known.add(asked.ends.get(c), asked.befores.get(c)));
                ends.add(asked.ends.get(c));
            }
            int extra = in.varint();
            if (extra > Batches.MAX_CANDIDATES) {
                throw new WireError(extra + " added candidates");
            }
            for (int e = 0; e < extra; e++) {
                double end = in.f64();
                IntersectionRecord before = new IntersectionRecord();
                Records.read(in, before, objects.reader());
                index.add(known.add(end, before));
                ends.add(end);
            }
            for (StandIn target : asked.targets) {
                int form = in.u8();
                if (form == Batches.ALL_MISSED) {
                    for (int c = 0; c < index.size(); c++) {
                        known.put(target, index.get(c), Answer.MISS);
                    }
                    continue;
                }
                if (form != Batches.WITH_BASE) {
                    throw new WireError("a target's answers of form " + form);
                }
                int base = in.varint() - 1;
                if (base >= index.size()) {
                    throw new WireError("a base answer of candidate " + base);
                }
                Answer baseAnswer = base < 0 ? null : Answer.read(in, objects.reader());
                Answer[] byCandidate = new Answer[index.size()];
                if (baseAnswer != null) {
                    for (int c = 0; c < byCandidate.length; c++) {
                        byCandidate[c] = baseAnswer.predict(key.startValue(), ends.get(c));
                    }
                }
                int explicit = in.varint();
                if (explicit > index.size()) {
                    throw new WireError(explicit + " explicit answers of " + index.size() + " candidates");
                }
                for (int e = 0; e < explicit; e++) {
                    int c = in.varint();
                    if (c >= index.size()) {
                        throw new WireError("candidate " + c + " of " + index.size());
                    }
                    int kind = in.u8();
                    if (kind == Batches.NEEDS) {
                        byCandidate[c] = null;
                    } else if (kind == Batches.ANSWERED) {
                        byCandidate[c] = Answer.read(in, objects.reader());
                    } else {
                        throw new WireError("an answer of kind " + kind);
                    }
                }
                for (int c = 0; c < byCandidate.length; c++) {
                    if (byCandidate[c] != null) {
                        known.put(target, index.get(c), byCandidate[c]);
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
                    throw new WireError("an answer of status " + status);
                }
                answers.put(calls.get(k).getKey(), answer);
            }
        }

        private void readNeeds(WireIn in, JudgeObjects objects) {
            int bases = in.count(Protocol.MAX_ENTRIES, "needed base answers");
            for (int k = 0; k < bases; k++) {
                Surface surface = objects.readJudgeSurface(in.i32());
                neededBases.put(new JudgeRay(surface, RayKey.of(Records.readKey(in))), true);
            }
            int exact = in.count(Protocol.MAX_ENTRIES, "needed exact answers");
            for (int k = 0; k < exact; k++) {
                Surface surface = objects.readJudgeSurface(in.i32());
                Ray key = Records.readKey(in);
                key.end = in.f64();
                IntersectionRecord before = new IntersectionRecord();
                Records.read(in, before, objects.reader());
                neededExact.add(new ExactQuestion(surface, key, before));
            }
        }
    }

    /** One step of a target's plan: a certified surface (and its handle), or a placement and the plan of what it places. */
    private static final class Step {
        final Surface surface;
        final int handle;
        final ray.surface.Transformed placed;
        final List<Step> inner;

        Step(Surface surface, int handle, ray.surface.Transformed placed, List<Step> inner) {
            this.surface = surface;
            this.handle = handle;
            this.placed = placed;
            this.inner = inner;
        }
    }

    /** A certified surface's answer to the ray with an endless segment, on a record of sentinels (so that every field it writes shows). */
    static Answer baseAnswer(Surface surface, Ray ray) {
        IntersectionRecord before = Sentinels.record();
        IntersectionRecord out = new IntersectionRecord();
        out.set(before);
        Ray asked = ray.copy();
        asked.end = Double.POSITIVE_INFINITY;
        try {
            boolean hit = surface.intersect(out, asked);
            return Answer.returned(hit, before, out, asked.start, Double.POSITIVE_INFINITY, asked);
        } catch (RuntimeException | Error e) {
            return Answer.threw(ThrownData.of(e, "ray.grading."));
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

        Answer baseAnswer() {
            return Rounds.baseAnswer(surface, key.ray(Double.POSITIVE_INFINITY));
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
