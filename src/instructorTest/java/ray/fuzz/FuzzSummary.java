package ray.fuzz;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Collectors;

/** The figures of a fuzz run, gathered from all workers, and their Markdown report. */
final class FuzzSummary {
    /** Failures listed in full; past these only counted. */
    private static final int FAILURES_LISTED = 50;

    private final long seed;
    private final long cases;
    private final int workers;
    private final Map<String, long[]> byRow = new LinkedHashMap<>();
    private final Map<String, Long> errorKinds = new HashMap<>();
    private final Map<String, Long> failureKinds = new HashMap<>();
    private final List<String> failures = new ArrayList<>();
    private final List<String> abandoned = new ArrayList<>();
    private final List<String> nonFiniteCases = new ArrayList<>();
    private long done;
    private long failed;
    private long unchanged;
    private long nonFiniteRenders;
    private long caseNanos;
    private long slowestNanos;
    private String slowest = "";
    private long wallNanos;

    FuzzSummary(long seed, long cases, int workers) {
        this.seed = seed;
        this.cases = cases;
        this.workers = workers;
        for (FileKind kind : FileKind.values()) {
            for (Mutation m : Mutation.values()) {
                if (m.appliesTo(kind)) {
                    byRow.put(kind.label + ": " + m, new long[3]);
                }
            }
            byRow.put(kind.label + ": 2–3 stacked", new long[3]);
        }
    }

    synchronized void add(FuzzCase c, Outcome o, boolean sameBytes) {
        done++;
        String prefix = c.kind.label + ": ";
        String row = prefix + (c.mutations.size() == 1 ? c.mutations.get(0).toString() : "2–3 stacked");
        byRow.get(row)[o.kind.ordinal()]++;
        unchanged += sameBytes ? 1 : 0;
        caseNanos += o.nanos;
        if (o.nanos > slowestNanos) {
            slowestNanos = o.nanos;
            slowest = c.toString();
        }
        if (o.kind == Outcome.Kind.RENDERED && o.nonFinitePixels > 0) {
            nonFiniteRenders++;
            if (nonFiniteCases.size() < FAILURES_LISTED) {
                nonFiniteCases.add(c + ": " + o.nonFinitePixels + " of the window's pixels");
            }
        }
        if (o.kind == Outcome.Kind.ERROR) {
            errorKinds.merge(kindOf(o.message), 1L, Long::sum);
        }
        if (o.kind == Outcome.Kind.FAILED) {
            failed++;
            failureKinds.merge(kindOf(o.message), 1L, Long::sum);
            if (failures.size() < FAILURES_LISTED) {
                failures.add(c + ": " + o.message);
            }
        }
    }

    synchronized void abandoned(int worker, long index) {
        abandoned.add("worker " + worker + " stopped at case " + index + " (a hang)");
    }

    synchronized void finish(long wallNanos) {
        this.wallNanos = wallNanos;
    }

    synchronized long failed() {
        return failed;
    }

    synchronized long done() {
        return done;
    }

    synchronized List<String> failures() {
        return new ArrayList<>(failures);
    }

    /** Cases that ended in each {@link Outcome.Kind}, all rows together. */
    synchronized long count(Outcome.Kind kind) {
        return byRow.values().stream().mapToLong(r -> r[kind.ordinal()]).sum();
    }

    /** Cases of one row ("scene: NUMBER", "mesh: 2–3 stacked", ...), by outcome. */
    synchronized long[] row(String name) {
        return byRow.get(name).clone();
    }

    /**
     * An error's problem with its particulars taken out (quoted text, numbers, paths, element names),
     * so that errors of one kind are counted together.
     */
    static String kindOf(String problem) {
        return problem.replaceAll("\"[^\"]*\"", "\"…\"")
                .replaceAll("'[^']*'", "'…'")
                // An absolute path (after a space), not the "/" of an end tag.
                .replaceAll("(?<=\\s)/[^\\s;:]+", "PATH")
                // A number standing alone, not the 8 of UTF-8.
                .replaceAll("(?<![\\w.-])[-+]?\\d+(\\.\\d+)?([eE][-+]?\\d+)?", "N")
                .replaceAll("<(/?)[^<>\\s/]+>", "<$1…>");
    }

    synchronized String markdown() {
        StringBuilder s = new StringBuilder();
        s.append(String.format(Locale.ROOT, "Seed %d, %d of %d cases run on %d workers in %.1f s (%.2f ms per case on average,"
                + " slowest %.0f ms: %s).%n%n", seed, done, cases, workers, wallNanos / 1e9, caseNanos / 1e6 / Math.max(1, done),
                slowestNanos / 1e6, slowest));
        s.append(String.format(Locale.ROOT, "**%d failures** (exceptions other than a located error, badly formed errors, hangs,"
                + " out of memory). %d renders, %d clean errors. %d cases left the file unchanged (nothing to mutate);"
                + " %d renders had pixels whose radiance is not finite.%n%n", failed, count(Outcome.Kind.RENDERED),
                count(Outcome.Kind.ERROR), unchanged, nonFiniteRenders));
        s.append("| damaged file: mutation | cases | rendered | clean error | failed |\n|---|---:|---:|---:|---:|\n");
        for (Map.Entry<String, long[]> e : byRow.entrySet()) {
            long[] r = e.getValue();
            s.append(String.format(Locale.ROOT, "| %s | %d | %d | %d | %d |%n", e.getKey(), r[0] + r[1] + r[2], r[0], r[1], r[2]));
        }
        s.append("\nThe most frequent errors (particulars replaced by …, N and PATH):\n\n| errors | problem |\n|---:|---|\n");
        List<Map.Entry<String, Long>> kinds = errorKinds.entrySet().stream()
                .sorted(Map.Entry.<String, Long>comparingByValue().reversed().thenComparing(Map.Entry.comparingByKey()))
                .collect(Collectors.toList());
        for (Map.Entry<String, Long> e : kinds.subList(0, Math.min(25, kinds.size()))) {
            s.append("| ").append(e.getValue()).append(" | ").append(e.getKey().replace("|", "\\|")).append(" |\n");
        }
        s.append(String.format(Locale.ROOT, "%n%d kinds of error in all.%n", kinds.size()));
        if (!nonFiniteCases.isEmpty()) {
            s.append("\nRenders with radiance that is not finite (shown as black or white):\n\n");
            nonFiniteCases.forEach(n -> s.append("- ").append(n).append('\n'));
        }
        if (!failures.isEmpty() || !abandoned.isEmpty()) {
            s.append("\nFailures by kind:\n\n| failures | what |\n|---:|---|\n");
            failureKinds.entrySet().stream()
                    .sorted(Map.Entry.<String, Long>comparingByValue().reversed().thenComparing(Map.Entry.comparingByKey()))
                    .forEach(e -> s.append("| ").append(e.getValue()).append(" | ").append(e.getKey().replace("|", "\\|"))
                            .append(" |\n"));
            s.append("\nThe first failures:\n\n");
            for (String f : failures) {
                s.append("- ").append(f).append('\n');
            }
            for (String a : abandoned) {
                s.append("- ").append(a).append('\n');
            }
        }
        return s.toString();
    }
}
