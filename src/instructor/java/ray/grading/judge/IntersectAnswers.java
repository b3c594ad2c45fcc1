package ray.grading.judge;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import ray.IntersectionRecord;
import ray.grading.wire.Answer;
import ray.grading.wire.RecordValues;

/**
 * The intersect answers the worker has given in this computation's rounds, by ray: for each ray,
 * the questions asked of it (candidates: a segment end and the record before), and for each
 * stand-in asked, its answer to each candidate. A question is answered here only when exactly it was
 * answered: the same stand-in, ray, end and record. Filled between rounds, read by the render's
 * threads during them.
 */
final class IntersectAnswers {
    private final Map<RayKey, PerRay> rays = new HashMap<>();

    /** The questions and answers of one ray. */
    static final class PerRay {
        final List<Double> ends = new ArrayList<>(2);
        final List<IntersectionRecord> befores = new ArrayList<>(2);
        /** The stand-ins asked, and for each its answers by candidate (null where not known). */
        final List<Object> targets = new ArrayList<>(2);
        final List<List<Answer>> answers = new ArrayList<>(2);

        List<Answer> answersOf(Object target) {
            for (int k = 0; k < targets.size(); k++) {
                if (targets.get(k) == target) {
                    return answers.get(k);
                }
            }
            return null;
        }

        /** The candidate's index, or −1. */
        int find(double end, IntersectionRecord before) {
            for (int c = 0; c < ends.size(); c++) {
                if (RecordValues.same(ends.get(c), end) && RecordValues.equal(befores.get(c), before)) {
                    return c;
                }
            }
            return -1;
        }

        /** The candidate's index, added when new (the record is copied). */
        int add(double end, IntersectionRecord before) {
            int found = find(end, before);
            if (found >= 0) {
                return found;
            }
            IntersectionRecord copy = new IntersectionRecord();
            copy.set(before);
            ends.add(end);
            befores.add(copy);
            return ends.size() - 1;
        }

        void put(Object target, int candidate, Answer answer) {
            List<Answer> answers = answersOf(target);
            if (answers == null) {
                answers = new ArrayList<>(2);
                targets.add(target);
                this.answers.add(answers);
            }
            while (answers.size() <= candidate) {
                answers.add(null);
            }
            answers.set(candidate, answer);
        }
    }

    /** The answer {@code target} gave to ({@code key} ending at {@code end}, record {@code before}), or null. */
    Answer lookup(Object target, RayKey key, double end, IntersectionRecord before) {
        PerRay ray = rays.get(key);
        if (ray == null) {
            return null;
        }
        List<Answer> answers = ray.answersOf(target);
        if (answers == null) {
            return null;
        }
        int c = ray.find(end, before);
        return c < 0 || c >= answers.size() ? null : answers.get(c);
    }

    PerRay ray(RayKey key) {
        return rays.computeIfAbsent(key, k -> new PerRay());
    }

    void clear() {
        rays.clear();
    }
}
