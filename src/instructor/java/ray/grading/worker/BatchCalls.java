package ray.grading.worker;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import ray.IntersectionRecord;
import ray.Ray;
import ray.camera.Camera;
import ray.grading.wire.Answer;
import ray.grading.wire.Batches;
import ray.grading.wire.Protocol;
import ray.grading.wire.RecordValues;
import ray.grading.wire.Records;
import ray.grading.wire.ThrownData;
import ray.grading.wire.WireError;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;
import ray.math.Vec3;
import ray.shading.Texture;
import ray.surface.Surface;

/**
 * Answers a batch ({@link Batches} has the layout): every intersect target on every candidate of its
 * ray, and the candidates a search will ask next; every camera and texture call. A student's group
 * that calls a judge-side surface gets its answer from the tables the judge sent, or, when they lack
 * it, a miss for now and a note of what is needed: that evaluation is then no answer, and the judge
 * asks again once it has sent what was needed.
 */
final class BatchCalls {
    private final WorkerObjects objects;
    private final JudgeLink link;

    BatchCalls(WorkerObjects objects, JudgeLink link) {
        this.objects = objects;
        this.link = link;
    }

    /** One batch being answered: its rays, the judge's tables, and what evaluations needed beyond them. */
    final class Running {
        private final List<Ray> rays;
        /** The batch's rays by value, made when first needed (a ray the student's code made anew). */
        private Map<Key, Integer> rayIndex;
        /** Per ray index, the judge's base answers: handles sorted, answers alike. */
        private final int[][] baseHandles;
        private final Answer[][] baseAnswers;
        private final Map<Key, Answer> exact = new HashMap<>();
        final Map<Key, Boolean> neededBases = new LinkedHashMap<>();
        final Map<Key, IntersectionRecord> neededExact = new LinkedHashMap<>();
        /** The ray being evaluated (its index), for the quick way to a judge-side surface's table. */
        private int current = -1;
        /** The evaluation running used a judge-side answer it does not have. */
        boolean guessed;

        Running(List<Ray> rays) {
            this.rays = rays;
            this.baseHandles = new int[rays.size()][];
            this.baseAnswers = new Answer[rays.size()][];
        }

        /** The batch's index of a ray with this origin, direction and start, or −1. */
        private int indexOf(Ray ray) {
            if (current >= 0) {
                Ray c = rays.get(current);
                // The student's group passes its children copies of the ray it was given: the same vectors.
                if (ray.origin == c.origin && ray.direction == c.direction && RecordValues.same(ray.start, c.start)) {
                    return current;
                }
            }
            if (rayIndex == null) {
                rayIndex = new HashMap<>();
                for (int k = 0; k < rays.size(); k++) {
                    rayIndex.putIfAbsent(new Key(-1, rays.get(k), Double.NaN, null), k);
                }
            }
            return rayIndex.getOrDefault(new Key(-1, ray, Double.NaN, null), -1);
        }

        private Answer base(int ray, int handle) {
            int[] handles = baseHandles[ray];
            if (handles == null) {
                return null;
            }
            int k = java.util.Arrays.binarySearch(handles, handle);
            return k < 0 ? null : baseAnswers[ray][k];
        }

        /** Adds the base answers of one ray, by handle (a later answer for a handle replaces an earlier one). */
        private void addBases(int ray, int[] handles, Answer[] answers) {
            java.util.TreeMap<Integer, Answer> all = new java.util.TreeMap<>();
            if (baseHandles[ray] != null) {
                for (int k = 0; k < baseHandles[ray].length; k++) {
                    all.put(baseHandles[ray][k], baseAnswers[ray][k]);
                }
            }
            for (int k = 0; k < handles.length; k++) {
                all.put(handles[k], answers[k]);
            }
            baseHandles[ray] = all.keySet().stream().mapToInt(Integer::intValue).toArray();
            baseAnswers[ray] = all.values().toArray(new Answer[0]);
        }

        /** A judge-side surface's answer from the tables; a miss and a note of the need when they lack it. */
        boolean judgeAnswer(JudgeSurface surface, IntersectionRecord out, Ray ray) {
            if (ray.origin == null || ray.direction == null) {
                guessed = true;
                return false;
            }
            int r = indexOf(ray);
            if (surface.certified) {
                Answer base = r < 0 ? null : base(r, surface.handle);
                if (base == null) {
                    neededBases.put(new Key(surface.handle, ray, Double.NaN, null), true);
                    guessed = true;
                    return false;
                }
                return base.predict(ray.start, ray.end).applyTo(out, ray);
            }
            Answer answer = exact.get(new Key(surface.handle, ray, ray.end, out));
            if (answer == null) {
                IntersectionRecord before = new IntersectionRecord();
                before.set(out);
                neededExact.put(new Key(surface.handle, ray, ray.end, out), before);
                guessed = true;
                return false;
            }
            if (answer.status == Protocol.THREW) {
                throw new JudgeSurface.JudgeSideThrew(answer.thrown);
            }
            return answer.applyTo(out, ray);
        }
    }

    /** A BATCH message; its answer. */
    WireOut answer(WireIn in) {
        thrownBytesLeft = Batches.THROWN_BYTES;
        objects.define(in);
        objects.settle();
        int rayCount = in.count(Protocol.MAX_ENTRIES, "rays");
        List<Ray> rays = new ArrayList<>(rayCount);
        for (int k = 0; k < rayCount; k++) {
            rays.add(Records.readKey(in));
        }
        Running running = new Running(rays);
        List<RayCalls> intersects = readIntersects(in, rays);
        List<UvCall> cameraCalls = readUvCalls(in);
        List<UvCall> textureCalls = readUvCalls(in);
        int anyCount = in.varint();
        List<Object[]> anyHits = new ArrayList<>(Math.min(anyCount, 1 << 16));
        for (int k = 0; k < anyCount; k++) {
            Surface target = twinSurface(in.varint());
            int ray = in.varint();
            if (ray >= rayCount) {
                throw new WireError("ray " + ray + " of " + rayCount);
            }
            anyHits.add(new Object[] {target, rays.get(ray), in.f64()});
        }
        int baseGroups = in.count(Protocol.MAX_ENTRIES, "judge base answer groups");
        for (int g = 0; g < baseGroups; g++) {
            int ray = in.index(rayCount, "ray");
            int n = in.count(Protocol.MAX_PARTS, "judge base answers");
            int[] handles = new int[n];
            Answer[] answers = new Answer[n];
            for (int k = 0; k < n; k++) {
                handles[k] = in.i32();
                answers[k] = Answer.read(in, objects);
            }
            running.addBases(ray, handles, answers);
        }
        int exacts = in.count(Protocol.MAX_ENTRIES, "judge exact answers");
        for (int k = 0; k < exacts; k++) {
            int handle = in.i32();
            Ray ray = rays.get(in.index(rayCount, "ray"));
            double end = in.f64();
            IntersectionRecord before = new IntersectionRecord();
            Records.read(in, before, objects);
            running.exact.put(new Key(handle, ray, end, before), Answer.read(in, objects));
        }
        in.end();
        WireOut answer = new WireOut();
        answering = answer;
        link.inBatch(running);
        try {
            for (RayCalls ray : intersects) {
                ray.evaluate(running, answer);
            }
            for (UvCall call : cameraCalls) {
                call.camera(answer);
            }
            for (UvCall call : textureCalls) {
                call.texture(answer);
            }
            for (Object[] question : anyHits) {
                anyHit(running, (Surface) question[0], (Ray) question[1], (Double) question[2], answer);
            }
        } finally {
            link.inBatch(null);
        }
        answer.i32(running.neededBases.size());
        for (Key need : running.neededBases.keySet()) {
            answer.i32(need.handle);
            Records.writeKey(answer, need.ray);
        }
        answer.i32(running.neededExact.size());
        for (Map.Entry<Key, IntersectionRecord> need : running.neededExact.entrySet()) {
            answer.i32(need.getKey().handle);
            Records.writeKey(answer, need.getKey().ray);
            answer.f64(need.getKey().end);
            Records.write(answer, need.getValue(), objects);
        }
        return answer;
    }

    private List<RayCalls> readIntersects(WireIn in, List<Ray> rays) {
        int n = in.count(Protocol.MAX_ENTRIES, "intersect rays");
        List<RayCalls> list = new ArrayList<>(n);
        for (int k = 0; k < n; k++) {
            int index = in.varint();
            if (index >= rays.size()) {
                throw new WireError("ray " + index + " of " + rays.size());
            }
            int count = in.varint();
            if (count > Batches.MAX_CANDIDATES) {
                throw new WireError(count + " candidates");
            }
            List<Candidate> candidates = new ArrayList<>(count);
            for (int c = 0; c < count; c++) {
                double end = in.f64();
                IntersectionRecord before = new IntersectionRecord();
                Records.read(in, before, objects);
                candidates.add(new Candidate(end, before));
            }
            int targetCount = in.varint();
            List<Surface> targets = new ArrayList<>(Math.min(targetCount, 1024));
            for (int t = 0; t < targetCount; t++) {
                targets.add(twinSurface(in.varint()));
            }
            list.add(new RayCalls(index, rays.get(index), candidates, targets));
        }
        return list;
    }

    /** A target, by its twin's handle; a broken twin is a target whose every answer is what its making threw. */
    private Surface twinSurface(int handle) {
        try {
            return objects.target(handle);
        } catch (WorkerObjects.BrokenTwin b) {
            return new WorkerObjects.BrokenSurface(b.why);
        }
    }

    private List<UvCall> readUvCalls(WireIn in) {
        int n = in.count(Protocol.MAX_ENTRIES, "calls");
        List<UvCall> calls = new ArrayList<>(n);
        for (int k = 0; k < n; k++) {
            if (in.u8() != Protocol.REF_TWIN) {
                throw new WireError("a batch call on no twin");
            }
            calls.add(new UvCall(in.i32(), in.f64(), in.f64()));
        }
        return calls;
    }

    /**
     * Bytes of whole throwables this answer may still carry ({@link Batches#THROWN_BYTES}); later ones go
     * in brief. Code that throws on every call of a render (a static initializer that failed) would
     * otherwise fill an answer past what a frame may hold, and the first throwables are what the render
     * reports.
     */
    private long thrownBytesLeft;
    /** The answer being written, to stop adding candidates once it holds {@link Batches#SPECULATED_BYTES}. */
    private WireOut answering;

    /** What {@code t} is, as the judge is told: whole while this answer has room for it, then in brief. */
    private ThrownData thrown(Throwable t) {
        ThrownData data = WorkerCalls.thrownData(t);
        if (thrownBytesLeft <= 0) {
            return data.brief();
        }
        thrownBytesLeft -= data.estimatedBytes();
        return data;
    }

    /** About how many bytes the answer holds so far: what is written, and the needed judge-side answers to be written at its end. */
    private long answeredBytes(Running running) {
        return answering.size() + (long) Batches.ANSWER_BYTES_AT_MOST * (running.neededBases.size() + running.neededExact.size());
    }

    /** A target not run on an added candidate: it comes before the hit the candidate follows, and the search never asks it so. */
    private static final Answer SKIPPED = Answer.threw(new ThrownData("skipped", null, List.of(), null));

    /** A segment end and the record before, as a search asks; an added one says which hit it follows. */
    private static final class Candidate {
        final double end;
        final IntersectionRecord before;
        /** For an added candidate: the target and the candidate whose hit left the record so. */
        int fromTarget;
        int fromCandidate;

        Candidate(double end, IntersectionRecord before) {
            this.end = end;
            this.before = before;
        }

        boolean same(double otherEnd, IntersectionRecord other) {
            return RecordValues.same(end, otherEnd) && RecordValues.equal(before, other);
        }
    }

    /** The intersects of one ray: every target on every candidate. */
    private final class RayCalls {
        final int index;
        final Ray key;
        final List<Candidate> candidates;
        final int asked;
        final List<Surface> targets;

        RayCalls(int index, Ray key, List<Candidate> candidates, List<Surface> targets) {
            this.index = index;
            this.key = key;
            this.candidates = candidates;
            this.asked = candidates.size();
            this.targets = targets;
        }

        void evaluate(Running running, WireOut out) {
            running.current = index;
            // answers.get(t).get(c): target t on candidate c; null when it needed what the judge did not send,
            // SKIPPED for a candidate added after a hit of target t or of a target after it.
            List<List<Answer>> answers = new ArrayList<>(targets.size());
            for (int t = 0; t < targets.size(); t++) {
                answers.add(new ArrayList<>(candidates.size()));
            }
            boolean search = targets.size() > 1 && targets.size() <= Batches.MAX_SEARCHED;
            for (int c = 0; c < candidates.size(); c++) {
                Candidate candidate = candidates.get(c);
                for (int t = 0; t < targets.size(); t++) {
                    if (c >= asked && t <= candidate.fromTarget) {
                        answers.get(t).add(SKIPPED);
                        continue;
                    }
                    Answer a = run(running, targets.get(t), candidate);
                    answers.get(t).add(a);
                    // A search (a group's loop over its surfaces, a few dozen a ray) asks the surfaces after a hit
                    // with the segment ending at it, and the record it left; a lone target is never asked again,
                    // and a loop over hundreds is no search.
                    if (search && t + 1 < targets.size() && a != null && a.status == Protocol.RETURNED && a.hit && (a.mask & Records.T) != 0) {
                        IntersectionRecord after = new IntersectionRecord();
                        after.set(candidate.before);
                        Records.apply(a.mask, a.written, after);
                        addCandidate(running, a.written.t, after, t, c);
                    }
                }
            }
            running.current = -1;
            // The added candidates, each with the target and candidate whose hit it follows (its record is the record
            // that hit left; the targets up to that one are not run on it); then each target's answers.
            out.varint(candidates.size() - asked);
            for (Candidate c : candidates.subList(asked, candidates.size())) {
                out.f64(c.end).varint(c.fromTarget).varint(c.fromCandidate);
            }
            for (int t = 0; t < targets.size(); t++) {
                writeTarget(answers.get(t), out);
            }
        }

        private void addCandidate(Running running, double end, IntersectionRecord before, int fromTarget, int fromCandidate) {
            if (candidates.size() >= Batches.MAX_CANDIDATES || answeredBytes(running) >= Batches.SPECULATED_BYTES) {
                return;
            }
            for (Candidate c : candidates) {
                if (c.same(end, before)) {
                    return;
                }
            }
            Candidate added = new Candidate(end, before);
            added.fromTarget = fromTarget;
            added.fromCandidate = fromCandidate;
            candidates.add(added);
        }

        /**
         * The base answer (the one with the farthest end that can be one) and every answer its rule does
         * not predict; a target that missed on every candidate, leaving everything alone, in one byte.
         */
        private void writeTarget(List<Answer> answers, WireOut out) {
            boolean allMissed = true;
            for (Answer a : answers) {
                allMissed &= a == SKIPPED || a != null && Answer.follows(a, Answer.MISS);
            }
            if (allMissed) {
                out.u8(Batches.ALL_MISSED);
                return;
            }
            out.u8(Batches.WITH_BASE);
            int base = -1;
            for (int c = 0; c < answers.size(); c++) {
                Answer a = answers.get(c);
                if (a != null && a != SKIPPED && a.isBase() && (base < 0 || candidates.get(c).end > candidates.get(base).end)) {
                    base = c;
                }
            }
            out.varint(base + 1);
            Answer baseAnswer = base < 0 ? null : answers.get(base);
            if (baseAnswer != null) {
                baseAnswer.write(out, objects);
            }
            List<Integer> explicit = new ArrayList<>();
            for (int c = 0; c < answers.size(); c++) {
                Answer a = answers.get(c);
                if (a != SKIPPED && (a == null || baseAnswer == null || !Answer.follows(a, baseAnswer.predict(key.start, candidates.get(c).end)))) {
                    explicit.add(c);
                }
            }
            out.varint(explicit.size());
            for (int c : explicit) {
                out.varint(c);
                Answer a = answers.get(c);
                if (a == null) {
                    out.u8(Batches.NEEDS);
                } else {
                    out.u8(Batches.ANSWERED);
                    a.write(out, objects);
                }
            }
        }

        /** The target's answer on the candidate, or null when it needed a judge-side answer it was not given. */
        private Answer run(Running running, Surface target, Candidate candidate) {
            IntersectionRecord out = new IntersectionRecord();
            out.set(candidate.before);
            Ray ray = new Ray(key.origin, key.direction, key.start, candidate.end);
            running.guessed = false;
            Answer answer;
            try {
                boolean hit = target.intersect(out, ray);
                answer = Answer.returned(hit, candidate.before, out, key.start, candidate.end, ray);
            } catch (Throwable t) { // whatever the student's code throws is its answer
                answer = Answer.threw(thrown(t));
            }
            return running.guessed ? null : answer;
        }
    }

    /** Whether anything of the target lies on the ray's segment (a shadow ray's question); what it needed, when it did. */
    private void anyHit(Running running, Surface target, Ray key, double end, WireOut out) {
        running.guessed = false;
        boolean hit;
        try {
            hit = target.intersectsAny(new Ray(key.origin, key.direction, key.start, end));
        } catch (Throwable t) { // whatever the student's code throws is its answer
            out.u8(Protocol.THREW);
            thrown(t).write(out);
            return;
        }
        if (running.guessed) {
            out.u8(Protocol.NEED);
            return;
        }
        out.u8(Protocol.RETURNED).bool(hit);
    }

    /** A camera or texture call. */
    private final class UvCall {
        final int handle;
        final double u;
        final double v;

        UvCall(int handle, double u, double v) {
            this.handle = handle;
            this.u = u;
            this.v = v;
        }

        void camera(WireOut out) {
            Ray ray;
            try {
                ray = objects.twin(handle, Camera.class).generateRay(u, v);
            } catch (Throwable t) {
                out.u8(Protocol.THREW);
                thrown(t).write(out);
                return;
            }
            out.u8(Protocol.RETURNED);
            Records.writeRayOrNull(out, ray);
        }

        void texture(WireOut out) {
            Vec3 color;
            try {
                color = objects.twin(handle, Texture.class).getTexColor(u, v);
            } catch (Throwable t) {
                out.u8(Protocol.THREW);
                thrown(t).write(out);
                return;
            }
            out.u8(Protocol.RETURNED).vec(color);
        }
    }

    /**
     * A judge-side question as a key: a handle (−1 for a ray alone), a ray's origin, direction and
     * start, and for an exact question the segment end and the record before.
     */
    private static final class Key {
        final int handle;
        final Ray ray;
        final double end;
        final IntersectionRecord before;
        private final int hash;

        Key(int handle, Ray ray, double end, IntersectionRecord before) {
            this.handle = handle;
            this.ray = ray;
            this.end = end;
            this.before = before;
            long h = handle;
            h = h * 31 + bits(ray.origin);
            h = h * 31 + bits(ray.direction);
            h = h * 31 + Double.doubleToRawLongBits(ray.start);
            h = h * 31 + Double.doubleToRawLongBits(end);
            h = h * 31 + (before == null ? 0 : RecordValues.hash(before));
            this.hash = Long.hashCode(h * 0x9E3779B97F4A7C15L);
        }

        @Override
        public int hashCode() {
            return hash;
        }

        @Override
        public boolean equals(Object o) {
            if (!(o instanceof Key)) {
                return false;
            }
            Key k = (Key) o;
            return k.hash == hash && k.handle == handle && RecordValues.same(k.ray.origin, ray.origin)
                    && RecordValues.same(k.ray.direction, ray.direction) && RecordValues.same(k.ray.start, ray.start)
                    && RecordValues.same(k.end, end) && (k.before == null ? before == null : before != null && RecordValues.equal(k.before, before));
        }

        private static long bits(Vec3 v) {
            return v == null ? 0 : (Double.doubleToRawLongBits(v.x) * 31 + Double.doubleToRawLongBits(v.y)) * 31 + Double.doubleToRawLongBits(v.z);
        }
    }
}
