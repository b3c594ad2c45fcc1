package ray.grading.judge;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import ray.IntersectionRecord;
import ray.Ray;
import ray.grading.wire.Answer;
import ray.grading.wire.Batches;
import ray.grading.wire.Protocol;
import ray.grading.wire.RecordValues;
import ray.grading.wire.Records;
import ray.grading.wire.ThrownData;
import ray.grading.wire.WireError;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;
import ray.surface.Surface;
import ray.surface.Transformed;

/**
 * One round's questions, from every computation that asked some, sent to the worker in as many
 * messages as their size needs ({@link Batches} has the layout), and each answer put into the
 * question that asked it. A computation's consecutive intersects of one ray go as one group (a
 * search: a group's loop, asking its surfaces one after another); the answers the worker adds for
 * the group go to the computation's pool. With a group whose targets are a student's groups go the
 * answers of the certified judge-side surfaces they hold, for the ray as they will pass it on.
 */
final class RoundBatch {
    /** A batch message stays below this size; more questions go in another message. */
    private static final int MESSAGE_BYTES = 24 << 20;

    private final Rounds rounds;
    private final List<Group> groups = new ArrayList<>();
    private final List<Question> cameraCalls = new ArrayList<>();
    private final List<Question> textureCalls = new ArrayList<>();
    private final List<Question> anyHits = new ArrayList<>();
    private final Map<JudgeRay, Answer> neededBases = new LinkedHashMap<>();
    private final List<Rounds.ExactQuestion> exactTable;

    /** A computation's consecutive intersects of one ray: its candidates (end and record before) and its targets. */
    private static final class Group {
        final Computation owner;
        final Question ray;
        final List<Question> asked = new ArrayList<>();
        final List<Question> candidates = new ArrayList<>();
        final List<Object> targets = new ArrayList<>();
        /** Each asked question's target and candidate (−1 when it had no room among the candidates). */
        final List<int[]> places = new ArrayList<>();

        Group(Computation owner, Question first) {
            this.owner = owner;
            this.ray = first;
        }

        void add(Question q) {
            asked.add(q);
            int c = candidate(q.end, q.before);
            if (c < 0 && candidates.size() < Batches.MAX_CANDIDATES) {
                c = candidates.size();
                candidates.add(q);
            }
            int t = target(q.target);
            if (t < 0) {
                t = targets.size();
                targets.add(q.target);
            }
            places.add(new int[] {t, c});
        }

        int candidate(double end, IntersectionRecord before) {
            for (int c = 0; c < candidates.size(); c++) {
                if (RecordValues.same(candidates.get(c).end, end) && RecordValues.equal(candidates.get(c).before, before)) {
                    return c;
                }
            }
            return -1;
        }

        int target(Object target) {
            for (int t = 0; t < targets.size(); t++) {
                if (targets.get(t) == target) {
                    return t;
                }
            }
            return -1;
        }
    }

    RoundBatch(Rounds rounds, List<Computation> computations, List<Rounds.ExactQuestion> exactTable) {
        this.rounds = rounds;
        this.exactTable = exactTable;
        for (Computation c : computations) {
            Group group = null;
            for (Question q : c.log) {
                if (q.answer != null || q.sent) {
                    continue;
                }
                q.sent = true;
                switch (q.kind) {
                    case INTERSECT:
                        if (group == null || !group.ray.sameRay(q)) {
                            group = new Group(c, q);
                            groups.add(group);
                        }
                        group.add(q);
                        break;
                    case ANY_HIT:
                        anyHits.add(q);
                        break;
                    case CAMERA:
                        cameraCalls.add(q);
                        break;
                    default:
                        textureCalls.add(q);
                }
            }
        }
        rounds.neededBases.keySet().forEach(r -> neededBases.put(r, r.baseAnswer()));
        rounds.neededBases.clear();
    }

    boolean isEmpty() {
        return groups.isEmpty() && cameraCalls.isEmpty() && textureCalls.isEmpty() && anyHits.isEmpty() && neededBases.isEmpty()
                && exactTable.isEmpty();
    }

    @Override
    public String toString() {
        return groups.size() + " intersect rays, " + anyHits.size() + " any-hit, " + cameraCalls.size() + " camera, "
                + textureCalls.size() + " texture, " + neededBases.size() + " bases, " + exactTable.size() + " exact";
    }

    /** The messages of this batch, each with where its sections start and stop (for reading its answer). */
    private final List<int[][]> sent = new ArrayList<>();

    /**
     * Writes the batch as messages of at most about {@link #MESSAGE_BYTES}, whose answers may take at
     * most about {@link Batches#ASKED_ANSWER_BYTES}, and sends them, not waiting for the answers.
     */
    void ask(Worker worker) {
        JudgeObjects objects = worker.objects();
        List<WireOut> messages = new ArrayList<>();
        int[] at = new int[4];
        boolean first = true;
        while (first || at[0] < groups.size() || at[1] < cameraCalls.size() || at[2] < textureCalls.size() || at[3] < anyHits.size()) {
            int[] from = at.clone();
            int[] to = new int[4];
            JudgeObjects.Message m = objects.new Message();
            write(m, from, to, first);
            messages.add(m.assembled());
            sent.add(new int[][] {from, to});
            at = to;
            first = false;
        }
        sentTo = worker.sendBatches(messages);
    }

    /** The worker the messages went to. */
    private Object sentTo;

    /** Reads the answers to the messages {@link #ask} sent, in order, into the questions. */
    void await(Worker worker) {
        for (int[][] message : sent) {
            worker.nextBatchAnswer(sentTo, in -> {
                read(in, worker.objects(), message[0], message[1]);
                return null;
            });
        }
    }

    /** One message: the rays it names, then each section, from {@code from}; {@code to} says where each section stopped. */
    private void write(JudgeObjects.Message m, int[] from, int[] to, boolean withTables) {
        Rays rays = new Rays();
        Map<Surface, List<Step>> plans = new IdentityHashMap<>();
        WireOut intersects = new WireOut();
        WireOut bases = new WireOut();
        int[] baseGroups = {0};
        // What the answers to this message's questions may take (Batches.ASKED_ANSWER_BYTES): its sections share it.
        long[] answerBytes = {0};
        int k = from[0];
        for (; k < groups.size() && (k == from[0] || intersects.size() + bases.size() < MESSAGE_BYTES && answerBytes[0] < Batches.ASKED_ANSWER_BYTES); k++) {
            Group g = groups.get(k);
            answerBytes[0] += (long) g.candidates.size() * g.targets.size() * Batches.ANSWER_BYTES_AT_MOST;
            int rayIndex = newRay(rays, g.ray);
            intersects.varint(rayIndex).varint(g.candidates.size());
            for (Question c : g.candidates) {
                intersects.f64(c.end);
                Records.write(intersects, c.before, m);
            }
            intersects.varint(g.targets.size());
            for (Object target : g.targets) {
                intersects.varint(m.target(target));
                if (target instanceof StandIn) {
                    List<Step> plan = plans.computeIfAbsent((Surface) target, t -> planOf(t, m, 0));
                    if (!plan.isEmpty()) {
                        prefetch(plan, g.ray.ray(Double.POSITIVE_INFINITY), rayIndex, rays, bases, baseGroups, m);
                    }
                }
            }
        }
        to[0] = k;
        WireOut cameras = new WireOut();
        to[1] = writeCalls(m, cameras, cameraCalls, from[1], answerBytes);
        WireOut textures = new WireOut();
        to[2] = writeCalls(m, textures, textureCalls, from[2], answerBytes);
        WireOut anys = new WireOut();
        int a = from[3];
        for (; a < anyHits.size() && (a == from[3] || anys.size() < MESSAGE_BYTES && answerBytes[0] < Batches.ASKED_ANSWER_BYTES); a++) {
            Question q = anyHits.get(a);
            answerBytes[0] += Batches.ANSWER_BYTES_AT_MOST;
            anys.varint(m.target(q.target)).varint(newRay(rays, q)).f64(q.end);
        }
        to[3] = a;
        if (withTables) {
            for (Map.Entry<JudgeRay, Answer> e : neededBases.entrySet()) {
                bases.i32(rayIndex(rays, e.getKey().key)).i32(1).i32(m.judgeHandle(e.getKey().surface));
                e.getValue().write(bases, m);
                baseGroups[0]++;
            }
        }
        WireOut exact = new WireOut();
        List<Rounds.ExactQuestion> exactSent = withTables ? exactTable : List.of();
        exact.i32(exactSent.size());
        for (Rounds.ExactQuestion q : exactSent) {
            exact.i32(m.judgeHandle(q.surface)).i32(rayIndex(rays, RayKey.of(q.ray))).f64(q.ray.end);
            Records.write(exact, q.before, m);
            q.answer.write(exact, m);
        }
        WireOut body = m.body;
        body.i32(rays.count);
        body.raw(rays.keys);
        body.i32(to[0] - from[0]).raw(intersects).raw(cameras).raw(textures).varint(to[3] - from[3]).raw(anys)
                .i32(baseGroups[0]).raw(bases).raw(exact);
    }

    /**
     * A message's rays: each question's ray written once as it comes (a computation's questions rarely
     * share one with another's), and those of the judge's tables, which their groups share, once each.
     */
    private static final class Rays {
        final WireOut keys = new WireOut();
        int count;
        final Map<RayKey, Integer> shared = new java.util.HashMap<>();
    }

    private static int newRay(Rays rays, Question q) {
        rays.keys.f64(q.origin.x).f64(q.origin.y).f64(q.origin.z).f64(q.direction.x).f64(q.direction.y).f64(q.direction.z).f64(q.start);
        return rays.count++;
    }

    private static int rayIndex(Rays rays, RayKey key) {
        Integer known = rays.shared.get(key);
        if (known == null) {
            known = rays.count++;
            Records.writeKey(rays.keys, key.ray(Double.POSITIVE_INFINITY));
            rays.shared.put(key, known);
        }
        return known;
    }

    private static int writeCalls(JudgeObjects.Message m, WireOut section, List<Question> calls, int from, long[] answerBytes) {
        WireOut entries = new WireOut();
        int k = from;
        for (; k < calls.size() && (k == from || entries.size() < MESSAGE_BYTES && answerBytes[0] < Batches.ASKED_ANSWER_BYTES); k++) {
            Question q = calls.get(k);
            answerBytes[0] += Batches.ANSWER_BYTES_AT_MOST;
            entries.u8(Protocol.REF_TWIN).i32(m.target(q.target)).f64(q.u).f64(q.v);
        }
        section.i32(k - from).raw(entries);
        return k;
    }

    /**
     * The answers of the certified judge-side surfaces that a target passes {@code ray} to, with an
     * endless segment, as one group of the base table: a student's group passes its children the ray
     * it was given, and a placement passes it in its own coordinates (a group of its own).
     */
    private void prefetch(List<Step> plan, Ray ray, int rayIndex, Rays rays, WireOut bases, int[] groups,
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
                    prefetch(step.inner, local, rayIndex(rays, RayKey.of(local)), rays, bases, groups, m);
                }
            }
        }
    }

    /**
     * What a target passes a ray to, found once per message: each certified judge-side surface among its
     * parts (through the parts of stand-ins it holds, a student's nested groups), and each placement of
     * a stand-in with the plan of what it places.
     */
    private static List<Step> planOf(Surface target, JudgeObjects.Message m, int depth) {
        List<Step> plan = new ArrayList<>();
        if (depth > 32) {
            return plan;
        }
        Certification certification = Worker.get().objects().certification();
        for (Surface child : target.children()) {
            if (StudentCalls.isRemote(child)) {
                plan.addAll(planOf(child, m, depth + 1));
            } else if (child instanceof Transformed && certification.holdsStandIn(child)) {
                Transformed placed = (Transformed) child;
                List<Step> inner = StudentCalls.isRemote(placed.placed()) ? planOf(placed.placed(), m, depth + 1) : List.of();
                if (!inner.isEmpty()) {
                    plan.add(new Step(null, 0, placed, inner));
                }
            } else if (certification.certified(child)) {
                plan.add(new Step(child, m.judgeHandle(child), null, null));
            }
        }
        return plan;
    }

    private void read(WireIn in, JudgeObjects objects, int[] from, int[] to) {
        for (int k = from[0]; k < to[0]; k++) {
            readGroup(in, objects, groups.get(k));
        }
        for (int k = from[1]; k < to[1]; k++) {
            cameraCalls.get(k).answer = readUv(in, true);
        }
        for (int k = from[2]; k < to[2]; k++) {
            textureCalls.get(k).answer = readUv(in, false);
        }
        for (int k = from[3]; k < to[3]; k++) {
            Question q = anyHits.get(k);
            int status = in.u8();
            if (status == Protocol.RETURNED) {
                q.answer = in.bool();
            } else if (status == Protocol.THREW) {
                q.answer = ThrownData.read(in);
            } else if (status == Protocol.NEED) {
                q.sent = false;
            } else {
                throw new WireError("an any-hit answer of status " + status);
            }
        }
        readNeeds(in, objects);
    }

    private static Object readUv(WireIn in, boolean camera) {
        int status = in.u8();
        if (status == Protocol.THREW) {
            return ThrownData.read(in);
        }
        if (status != Protocol.RETURNED) {
            throw new WireError("an answer of status " + status);
        }
        Object value = camera ? Records.readRayOrNull(in) : in.vec();
        return value == null ? Question.NULL : value;
    }

    /** A group's answers: each asked question's, and the rest (the added candidates' too) into the owner's pool. */
    private void readGroup(WireIn in, JudgeObjects objects, Group g) {
        int asked = g.candidates.size();
        int extra = in.varint();
        if (extra > Batches.MAX_CANDIDATES - asked) {
            throw new WireError(extra + " added candidates");
        }
        List<Double> ends = new ArrayList<>(asked + extra);
        g.candidates.forEach(c -> ends.add(c.end));
        int[][] from = new int[extra][];
        for (int e = 0; e < extra; e++) {
            ends.add(in.f64());
            from[e] = new int[] {in.varint(), in.varint()};
            if (from[e][0] >= g.targets.size() || from[e][1] >= asked + e) {
                throw new WireError("an added candidate that follows no earlier hit");
            }
        }
        Answer[][] answers = new Answer[g.targets.size()][];
        for (int t = 0; t < answers.length; t++) {
            answers[t] = readTarget(in, objects, g.ray.start, ends);
            // The targets up to the one whose hit a candidate follows were not run on it.
            for (int e = 0; e < extra; e++) {
                if (t <= from[e][0]) {
                    answers[t][asked + e] = null;
                }
            }
        }
        // Each added candidate's record is what the hit it follows left: the record before that candidate, changed by the hit.
        List<IntersectionRecord> befores = new ArrayList<>(asked + extra);
        g.candidates.forEach(c -> befores.add(c.before));
        for (int e = 0; e < extra; e++) {
            Answer hit = answers[from[e][0]][from[e][1]];
            if (hit == null || hit.status != Protocol.RETURNED || !hit.hit) {
                throw new WireError("an added candidate that follows no hit");
            }
            IntersectionRecord before = new IntersectionRecord();
            before.set(befores.get(from[e][1]));
            Records.apply(hit.mask, hit.written, before);
            befores.add(before);
        }
        // The asked questions by target and candidate; every other answer goes to the pool.
        Question[][] byPlace = new Question[g.targets.size()][asked];
        for (int k = 0; k < g.asked.size(); k++) {
            int[] place = g.places.get(k);
            if (place[1] >= 0) {
                byPlace[place[0]][place[1]] = g.asked.get(k);
            }
        }
        for (int t = 0; t < answers.length; t++) {
            for (int c = 0; c < answers[t].length; c++) {
                if (answers[t][c] == null) {
                    continue;
                }
                Question q = c < asked ? byPlace[t][c] : null;
                if (q != null) {
                    q.answer = answers[t][c];
                } else if (g.targets.size() <= Batches.MAX_SEARCHED) {
                    // What a search asks next; a loop over hundreds of targets is no search, and its pool would be large.
                    g.owner.pool(Question.answered(g.targets.get(t), g.ray.origin, g.ray.direction, g.ray.start, ends.get(c),
                            befores.get(c), answers[t][c]));
                }
            }
        }
        // A question the worker could not answer yet (it needed judge-side answers) is asked again.
        for (Question q : g.asked) {
            if (q.answer == null) {
                q.sent = false;
            }
        }
    }

    /** One target's answers by candidate (null where it needed more): all missed, or a base and the answers its rule does not predict. */
    private static Answer[] readTarget(WireIn in, JudgeObjects objects, double start, List<Double> ends) {
        Answer[] byCandidate = new Answer[ends.size()];
        int form = in.u8();
        if (form == Batches.ALL_MISSED) {
            java.util.Arrays.fill(byCandidate, Answer.MISS);
            return byCandidate;
        }
        if (form != Batches.WITH_BASE) {
            throw new WireError("a target's answers of form " + form);
        }
        int base = in.varint() - 1;
        if (base >= ends.size()) {
            throw new WireError("a base answer of candidate " + base);
        }
        Answer baseAnswer = base < 0 ? null : Answer.read(in, objects.reader());
        if (baseAnswer != null) {
            for (int c = 0; c < byCandidate.length; c++) {
                byCandidate[c] = baseAnswer.predict(start, ends.get(c));
            }
        }
        int explicit = in.varint();
        if (explicit > ends.size()) {
            throw new WireError(explicit + " explicit answers of " + ends.size() + " candidates");
        }
        for (int e = 0; e < explicit; e++) {
            int c = in.varint();
            if (c >= ends.size()) {
                throw new WireError("candidate " + c + " of " + ends.size());
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
        return byCandidate;
    }

    private void readNeeds(WireIn in, JudgeObjects objects) {
        int bases = in.count(Protocol.MAX_ENTRIES, "needed base answers");
        for (int k = 0; k < bases; k++) {
            Surface surface = objects.readJudgeSurface(in.i32());
            rounds.neededBases.put(new JudgeRay(surface, RayKey.of(Records.readKey(in))), true);
        }
        int exact = in.count(Protocol.MAX_ENTRIES, "needed exact answers");
        for (int k = 0; k < exact; k++) {
            Surface surface = objects.readJudgeSurface(in.i32());
            Ray key = Records.readKey(in);
            key.end = in.f64();
            IntersectionRecord before = new IntersectionRecord();
            Records.read(in, before, objects.reader());
            rounds.neededExact.add(rounds.new ExactQuestion(surface, key, before));
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

    /** One step of a target's plan: a certified surface (and its handle), or a placement and the plan of what it places. */
    private static final class Step {
        final Surface surface;
        final int handle;
        final Transformed placed;
        final List<Step> inner;

        Step(Surface surface, int handle, Transformed placed, List<Step> inner) {
            this.surface = surface;
            this.handle = handle;
            this.placed = placed;
            this.inner = inner;
        }
    }

    /** A certified judge-side surface and a ray, whose endless answer the worker derives the others from. */
    static final class JudgeRay {
        final Surface surface;
        final RayKey key;

        JudgeRay(Surface surface, RayKey key) {
            this.surface = surface;
            this.key = key;
        }

        Answer baseAnswer() {
            return RoundBatch.baseAnswer(surface, key.ray(Double.POSITIVE_INFINITY));
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
}
