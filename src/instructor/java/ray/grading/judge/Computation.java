package ray.grading.judge;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import ray.IntersectionRecord;
import ray.Ray;

/**
 * What one computation (a pixel, a test's block) asked in its last run, in order: its log. Running
 * again, a computation mostly asks what it asked before in the same order, so each call is first
 * checked against the log's next question; a call the answers sent another way (a loop that now
 * stops early, a search that now prunes) is looked up in the whole log, and else in the pool of
 * answers the worker gave unasked (what a search asks next); only then is it a new question. The
 * questions used in a run are the next run's log.
 */
final class Computation {
    /** Logs and pools longer than this are looked up by hash when a call leaves the log's order; shorter ones by a scan. */
    private static final int SCANNED = 16;

    List<Question> log = new ArrayList<>();
    /** The log, found by hash when a call leaves its order; made when first needed, anew for each log. */
    private Hashed logByHash;
    private final Hashed pool = new Hashed(new ArrayList<>(0));
    private List<Question> next = new ArrayList<>();
    private int cursor;
    /** This run used a question without an answer. */
    boolean guessed;
    /** This run asked a question not sent yet: the next batch takes it. */
    boolean asking;

    /** Starts a run: the log is read from its beginning. */
    void begin() {
        cursor = 0;
        guessed = false;
        asking = false;
        next = new ArrayList<>(log.size());
    }

    /** Ends a run: the questions it used are the log. */
    void end() {
        log = next;
        next = null;
        logByHash = null;
    }

    /** Notes that this run used {@code q}'s answer, which is unknown: a guess, and a question to send unless it was. */
    void unknown(Question q) {
        guessed = true;
        asking |= !q.sent;
    }

    Question intersect(Object target, Ray ray, IntersectionRecord out) {
        if (cursor < log.size() && log.get(cursor).matchesIntersect(target, ray, out)) {
            return used(log.get(cursor++));
        }
        int hash = Question.intersectHash(target, ray, out);
        for (Question q : candidates(hash)) {
            if (q.matchesIntersect(target, ray, out)) {
                return used(q);
            }
        }
        for (Question q : pooled(hash)) {
            if (q.matchesIntersect(target, ray, out)) {
                return used(q);
            }
        }
        return used(Question.intersect(target, ray, out));
    }

    Question anyHit(Object target, Ray ray) {
        if (cursor < log.size() && log.get(cursor).matchesAnyHit(target, ray)) {
            return used(log.get(cursor++));
        }
        for (Question q : candidates(Question.anyHitHash(target, ray))) {
            if (q.matchesAnyHit(target, ray)) {
                return used(q);
            }
        }
        return used(Question.anyHit(target, ray));
    }

    Question uv(Question.Kind kind, Object target, double u, double v) {
        if (cursor < log.size() && log.get(cursor).matchesUv(kind, target, u, v)) {
            return used(log.get(cursor++));
        }
        for (Question q : candidates(Question.uvHash(target, u, v))) {
            if (q.matchesUv(kind, target, u, v)) {
                return used(q);
            }
        }
        return used(Question.uv(kind, target, u, v));
    }

    /** The log's questions that may match a call whose inputs hash to {@code hash}. */
    private List<Question> candidates(int hash) {
        if (logByHash == null) {
            logByHash = new Hashed(log);
        }
        return logByHash.candidates(hash);
    }

    /** Keeps an answer the worker gave unasked (what a search asks next), for a later run's call to find. */
    void pool(Question answered) {
        pool.add(answered);
    }

    /** The pool's answers that may match a call whose inputs hash to {@code hash}. */
    private List<Question> pooled(int hash) {
        return pool.candidates(hash);
    }

    /** Questions looked up by their inputs' hash: all of them while they are few, else those of that hash (indexed when first needed). */
    private static final class Hashed {
        private final List<Question> all;
        private Map<Integer, List<Question>> byHash;

        Hashed(List<Question> all) {
            this.all = all;
        }

        void add(Question q) {
            all.add(q);
            if (byHash != null) {
                byHash.computeIfAbsent(q.hash(), h -> new ArrayList<>(1)).add(q);
            }
        }

        List<Question> candidates(int hash) {
            if (all.size() <= SCANNED) {
                return all;
            }
            if (byHash == null) {
                byHash = new HashMap<>();
                for (Question q : all) {
                    byHash.computeIfAbsent(q.hash(), h -> new ArrayList<>(1)).add(q);
                }
            }
            return byHash.getOrDefault(hash, List.of());
        }
    }

    private Question used(Question q) {
        next.add(q);
        return q;
    }
}
