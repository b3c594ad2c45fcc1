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
 * that calls a judge-side surface gets its answer from the tables the judge sent, or, when the
 * table lacks it, a miss for now and a note of what is needed; that evaluation is then not an
 * answer, and the judge asks again once it has sent what was needed.
 */
final class BatchCalls {
    private final WorkerObjects objects;
    private final JudgeLink link;

    BatchCalls(WorkerObjects objects, JudgeLink link) {
        this.objects = objects;
        this.link = link;
    }

    /** One batch being answered: the judge's tables, and what evaluations needed beyond them. */
    final class Running {
        private final Map<RayKey, Answer> bases = new HashMap<>();
        private final Map<ExactKey, Answer> exact = new HashMap<>();
        final Map<RayKey, Boolean> neededBases = new LinkedHashMap<>();
        final Map<ExactKey, IntersectionRecord> neededExact = new LinkedHashMap<>();
        /** The evaluation running used a judge-side answer it does not have. */
        boolean guessed;

        /** A judge-side surface's answer from the tables; a miss and a note of the need when they lack it. */
        boolean judgeAnswer(JudgeSurface surface, IntersectionRecord out, Ray ray) {
            if (ray.origin == null || ray.direction == null) {
                guessed = true;
                return false;
            }
            if (surface.certified) {
                RayKey key = new RayKey(surface.handle, ray);
                Answer base = bases.get(key);
                if (base == null) {
                    neededBases.put(key, true);
                    guessed = true;
                    return false;
                }
                return base.predict(ray.start, ray.end).applyTo(out, ray);
            }
            ExactKey key = new ExactKey(surface.handle, ray, out);
            Answer answer = exact.get(key);
            if (answer == null) {
                IntersectionRecord before = new IntersectionRecord();
                before.set(out);
                neededExact.put(key, before);
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
        objects.define(in);
        objects.settle();
        WireOut answer = new WireOut();
        Running running = new Running();
        List<RayCalls> rays = readRays(in);
        List<UvCall> cameraCalls = readUvCalls(in);
        List<UvCall> textureCalls = readUvCalls(in);
        int bases = in.count(Protocol.MAX_ENTRIES, "judge base answers");
        for (int k = 0; k < bases; k++) {
            int handle = in.i32();
            RayKey key = new RayKey(handle, readKeyRay(in));
            running.bases.put(key, Answer.read(in, objects));
        }
        int exacts = in.count(Protocol.MAX_ENTRIES, "judge exact answers");
        for (int k = 0; k < exacts; k++) {
            int handle = in.i32();
            Ray ray = Records.readRay(in);
            IntersectionRecord record = new IntersectionRecord();
            Records.read(in, record, objects);
            running.exact.put(new ExactKey(handle, ray, record), Answer.read(in, objects));
        }
        in.end();
        link.inBatch(running);
        try {
            for (RayCalls ray : rays) {
                ray.evaluate(running, answer);
            }
            for (UvCall call : cameraCalls) {
                call.camera(answer);
            }
            for (UvCall call : textureCalls) {
                call.texture(answer);
            }
        } finally {
            link.inBatch(null);
        }
        answer.i32(running.neededBases.size());
        for (RayKey key : running.neededBases.keySet()) {
            answer.i32(key.handle);
            writeKeyRay(answer, key.ray);
        }
        answer.i32(running.neededExact.size());
        for (Map.Entry<ExactKey, IntersectionRecord> need : running.neededExact.entrySet()) {
            answer.i32(need.getKey().handle);
            Records.writeRay(answer, need.getKey().ray);
            Records.write(answer, need.getValue(), objects);
        }
        return answer;
    }

    private static Ray readKeyRay(WireIn in) {
        Vec3 origin = new Vec3(in.f64(), in.f64(), in.f64());
        Vec3 direction = new Vec3(in.f64(), in.f64(), in.f64());
        return new Ray(origin, direction, in.f64(), Double.POSITIVE_INFINITY);
    }

    private static void writeKeyRay(WireOut out, Ray ray) {
        out.f64(ray.origin.x).f64(ray.origin.y).f64(ray.origin.z).f64(ray.direction.x).f64(ray.direction.y).f64(ray.direction.z)
                .f64(ray.start);
    }

    private List<RayCalls> readRays(WireIn in) {
        int n = in.count(Protocol.MAX_ENTRIES, "rays");
        List<RayCalls> rays = new ArrayList<>(n);
        for (int k = 0; k < n; k++) {
            Ray key = readKeyRay(in);
            int candidates = in.count(Batches.MAX_CANDIDATES, "candidates");
            List<Candidate> list = new ArrayList<>();
            for (int c = 0; c < candidates; c++) {
                double end = in.f64();
                IntersectionRecord before = new IntersectionRecord();
                Records.read(in, before, objects);
                list.add(new Candidate(end, before));
            }
            int targets = in.count(Protocol.MAX_PARTS, "targets");
            List<Surface> list2 = new ArrayList<>(targets);
            for (int t = 0; t < targets; t++) {
                list2.add(twinSurface(in));
            }
            rays.add(new RayCalls(key, list, candidates, list2));
        }
        return rays;
    }

    /** A target: a twin reference; a broken twin is a target whose every answer is what its making threw. */
    private Surface twinSurface(WireIn in) {
        if (in.u8() != Protocol.REF_TWIN) {
            throw new WireError("a batch target that is no twin");
        }
        int handle = in.i32();
        try {
            return objects.twin(handle, Surface.class);
        } catch (WorkerObjects.BrokenTwin b) {
            return new Broken(b.why);
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

    /** A segment end and the record before, as a search asks. */
    private static final class Candidate {
        final double end;
        final IntersectionRecord before;

        Candidate(double end, IntersectionRecord before) {
            this.end = end;
            this.before = before;
        }

        boolean same(double otherEnd, IntersectionRecord other) {
            return Double.doubleToRawLongBits(end) == Double.doubleToRawLongBits(otherEnd) && RecordValues.equal(before, other);
        }
    }

    /** The intersects of one ray: every target on every candidate. */
    private final class RayCalls {
        final Ray key;
        final List<Candidate> candidates;
        final int asked;
        final List<Surface> targets;

        RayCalls(Ray key, List<Candidate> candidates, int asked, List<Surface> targets) {
            this.key = key;
            this.candidates = candidates;
            this.asked = asked;
            this.targets = targets;
        }

        void evaluate(Running running, WireOut out) {
            // answers.get(t).get(c): target t on candidate c; null when it needed what the judge did not send.
            List<List<Answer>> answers = new ArrayList<>();
            for (int t = 0; t < targets.size(); t++) {
                answers.add(new ArrayList<>());
            }
            for (int c = 0; c < candidates.size(); c++) {
                Candidate candidate = candidates.get(c);
                for (int t = 0; t < targets.size(); t++) {
                    Answer a = run(running, targets.get(t), candidate);
                    answers.get(t).add(a);
                    // A hit is what the other targets of a search are asked with next; one target alone is never asked again.
                    if (targets.size() > 1 && a != null && a.status == Protocol.RETURNED && a.hit && (a.mask & Records.T) != 0) {
                        IntersectionRecord after = new IntersectionRecord();
                        after.set(candidate.before);
                        Records.apply(a.mask, a.written, after);
                        addCandidate(a.written.t, after);
                        addCandidate(Math.nextUp(a.written.t), after);
                    }
                }
            }
            out.i32(candidates.size() - asked);
            for (Candidate c : candidates.subList(asked, candidates.size())) {
                out.f64(c.end);
                Records.write(out, c.before, objects);
            }
            for (int t = 0; t < targets.size(); t++) {
                writeTarget(answers.get(t), out);
            }
        }

        private void addCandidate(double end, IntersectionRecord before) {
            if (candidates.size() >= Batches.MAX_CANDIDATES) {
                return;
            }
            for (Candidate c : candidates) {
                if (c.same(end, before)) {
                    return;
                }
            }
            candidates.add(new Candidate(end, before));
        }

        private void writeTarget(List<Answer> answers, WireOut out) {
            int base = -1;
            for (int c = 0; c < answers.size(); c++) {
                Answer a = answers.get(c);
                if (a != null && a.isBase() && (base < 0 || candidates.get(c).end > candidates.get(base).end)) {
                    base = c;
                }
            }
            out.i32(base);
            Answer baseAnswer = base < 0 ? null : answers.get(base);
            if (baseAnswer != null) {
                baseAnswer.write(out, objects);
            }
            List<Integer> explicit = new ArrayList<>();
            for (int c = 0; c < answers.size(); c++) {
                Answer a = answers.get(c);
                if (a == null || baseAnswer == null || !Answer.follows(a, baseAnswer.predict(key.start, candidates.get(c).end))) {
                    explicit.add(c);
                }
            }
            out.i32(explicit.size());
            for (int c : explicit) {
                out.i32(c);
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
            if (target instanceof Broken) {
                return Answer.threw(((Broken) target).why);
            }
            IntersectionRecord out = new IntersectionRecord();
            out.set(candidate.before);
            Ray ray = new Ray(key.origin, key.direction, key.start, candidate.end);
            running.guessed = false;
            Answer answer;
            try {
                boolean hit = target.intersect(out, ray);
                answer = Answer.returned(hit, candidate.before, out, key.start, candidate.end, ray);
            } catch (Throwable t) { // whatever the student's code throws is its answer
                answer = Answer.threw(thrownData(t));
            }
            return running.guessed ? null : answer;
        }
    }

    private ThrownData thrownData(Throwable t) {
        if (t instanceof JudgeSurface.JudgeSideThrew) {
            return ((JudgeSurface.JudgeSideThrew) t).thrown;
        }
        if (t instanceof WorkerObjects.BrokenTwin) {
            return ((WorkerObjects.BrokenTwin) t).why;
        }
        return ThrownData.of(t, WorkerMain.OWN_PACKAGE);
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
                thrownData(t).write(out);
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
                thrownData(t).write(out);
                return;
            }
            out.u8(Protocol.RETURNED).vec(color);
        }
    }

    /** A target whose making threw. */
    private static final class Broken extends Surface {
        final ThrownData why;

        Broken(ThrownData why) {
            this.why = why;
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            return false;
        }
    }

    /** A judge surface's ray, for the base answers: the handle and the ray's origin, direction and start. */
    private static final class RayKey {
        final int handle;
        final Ray ray;
        private final int hash;

        RayKey(int handle, Ray ray) {
            this.handle = handle;
            this.ray = ray;
            this.hash = java.util.Objects.hash(handle, bits(ray.origin), bits(ray.direction), Double.doubleToRawLongBits(ray.start));
        }

        @Override
        public int hashCode() {
            return hash;
        }

        @Override
        public boolean equals(Object o) {
            if (!(o instanceof RayKey)) {
                return false;
            }
            RayKey k = (RayKey) o;
            return k.handle == handle && RecordValues.same(k.ray.origin, ray.origin) && RecordValues.same(k.ray.direction, ray.direction)
                    && RecordValues.same(k.ray.start, ray.start);
        }
    }

    /** A judge surface's exact question: the handle, the ray with its end, the record before. */
    private static final class ExactKey {
        final int handle;
        final Ray ray;
        final IntersectionRecord before;
        private final int hash;

        ExactKey(int handle, Ray ray, IntersectionRecord before) {
            this.handle = handle;
            this.ray = ray.copy();
            this.before = new IntersectionRecord();
            this.before.set(before);
            this.hash = java.util.Objects.hash(handle, bits(ray.origin), bits(ray.direction), Double.doubleToRawLongBits(ray.start),
                    Double.doubleToRawLongBits(ray.end), RecordValues.hash(before));
        }

        @Override
        public int hashCode() {
            return hash;
        }

        @Override
        public boolean equals(Object o) {
            if (!(o instanceof ExactKey)) {
                return false;
            }
            ExactKey k = (ExactKey) o;
            return k.handle == handle && RecordValues.same(k.ray.origin, ray.origin) && RecordValues.same(k.ray.direction, ray.direction)
                    && RecordValues.same(k.ray.start, ray.start) && RecordValues.same(k.ray.end, ray.end) && RecordValues.equal(k.before, before);
        }
    }

    private static long bits(Vec3 v) {
        return v == null ? 0 : Double.doubleToRawLongBits(v.x) * 31 + Double.doubleToRawLongBits(v.y) * 17 + Double.doubleToRawLongBits(v.z);
    }
}
