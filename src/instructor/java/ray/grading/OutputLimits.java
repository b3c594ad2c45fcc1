package ray.grading;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

/**
 * Bounds on what a submission can make the results file carry: student code chooses its exception
 * messages and what it prints, so each test's message and the overall output are cut to a length,
 * and the whole file is kept under {@link #RESULTS_BYTES} (PrairieLearn drops a larger one; Gradescope
 * slows to a crawl showing it) by leaving out pictures, then cutting text further.
 */
final class OutputLimits {
    /** A test's message: a full assertion or a stack trace's first lines fit easily. */
    static final int MESSAGE_CHARS = 4_000;
    /** The overall output: the graded-files list, compiler messages and notes. */
    static final int OUTPUT_CHARS = 50_000;
    /** The results file, as PrairieLearn limits it. */
    static final int RESULTS_BYTES = 1_000_000;
    /** Text cut at the last resort, when even without pictures the file is too large. */
    private static final int LAST_RESORT_CHARS = 300;
    static final String CUT = "\n… (cut)";

    private OutputLimits() {
    }

    /** {@code text} with at most {@code max} characters of its own, then "… (cut)" when it was longer. */
    static String cut(String text, int max) {
        if (text.length() <= max) {
            return text;
        }
        int end = Character.isHighSurrogate(text.charAt(max - 1)) ? max - 1 : max; // never half a character
        return text.substring(0, end) + CUT;
    }

    static List<TestOutcome> cutMessages(List<TestOutcome> outcomes, int max) {
        List<TestOutcome> cut = new ArrayList<>(outcomes.size());
        for (TestOutcome t : outcomes) {
            cut.add(t.message().length() <= max ? t : t.withMessage(cut(t.message(), max)));
        }
        return cut;
    }

    /** The size of the results as written (GradescopeResults.write's JSON, UTF-8). */
    static int bytes(Map<String, Object> results) {
        return GradescopeResults.json(results).getBytes(StandardCharsets.UTF_8).length;
    }

    /** Builds the results of these outcomes and output, with or without pictures. */
    interface Builder {
        Map<String, Object> build(List<TestOutcome> outcomes, String output, boolean pictures);
    }

    /**
     * The results within {@link #RESULTS_BYTES}: as built, or without pictures, or with every message
     * and the output cut to a few lines.
     */
    static Map<String, Object> within(List<TestOutcome> outcomes, String output, Builder builder) {
        List<Supplier<Map<String, Object>>> tries = List.of(
                () -> builder.build(cutMessages(outcomes, MESSAGE_CHARS), cut(output, OUTPUT_CHARS), true),
                () -> builder.build(cutMessages(outcomes, MESSAGE_CHARS), cut(output, OUTPUT_CHARS), false),
                () -> builder.build(cutMessages(outcomes, LAST_RESORT_CHARS), cut(output, 10 * LAST_RESORT_CHARS), false));
        Map<String, Object> results = null;
        for (Supplier<Map<String, Object>> attempt : tries) {
            results = attempt.get();
            if (bytes(results) <= RESULTS_BYTES) {
                return results;
            }
        }
        return results;
    }
}
