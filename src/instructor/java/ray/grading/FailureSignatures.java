package ray.grading;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Names known mistakes from a task's failed unit tests alone. A failure signature is the failed
 * regular unit tests (not render tests, not bonus tests, which correct code may fail too), each with
 * its message's numbers to six significant digits (and no line numbers of source files): the same
 * mistake written another way fails the same tests with the same numbers, give or take the last bits
 * of a double. A mistake is named when
 * the student's signature is exactly its own; and two are, each on the failures that are its own,
 * when the student's failed tests are exactly the two mistakes' together and every one of them
 * fails as one of the two does (two mistakes in two files of a task, say RepeatTexture and
 * ClampTexture). Where two mistakes, or two pairs, fit alike, nothing is named: they cannot be told
 * apart.
 */
final class FailureSignatures {
    static final String SAME_FAILURES = "Your code fails the same tests as a known mistake's, with the same numbers; its code ";
    static final String ONE_OF_TWO = "This failure, with the same numbers, is a known mistake's (your failed tests are exactly"
            + " those of two known mistakes together); its code ";

    private FailureSignatures() {
    }

    /**
     * The names for the student's failed tests, by test id.
     *
     * @param yours  the student's signature ({@link #of})
     * @param theirs each known mistake's description → its signature
     */
    static Map<String, String> named(Map<String, String> yours, Map<String, Map<String, String>> theirs) {
        Map<String, String> names = new LinkedHashMap<>();
        if (yours.isEmpty()) {
            return names;
        }
        List<String> same = new ArrayList<>();
        theirs.forEach((mistake, signature) -> {
            if (signature.equals(yours)) {
                same.add(mistake);
            }
        });
        if (same.size() == 1) {
            yours.keySet().forEach(id -> names.put(id, SAME_FAILURES + same.get(0)));
            return names;
        }
        if (!same.isEmpty()) {
            return names;
        }
        List<String[]> pairs = new ArrayList<>();
        List<String> mistakes = new ArrayList<>(theirs.keySet());
        for (int i = 0; i < mistakes.size(); i++) {
            for (int j = i + 1; j < mistakes.size(); j++) {
                if (together(yours, theirs.get(mistakes.get(i)), theirs.get(mistakes.get(j)))) {
                    pairs.add(new String[] {mistakes.get(i), mistakes.get(j)});
                }
            }
        }
        if (pairs.size() == 1) {
            for (String mistake : pairs.get(0)) {
                theirs.get(mistake).forEach((id, message) -> {
                    if (message.equals(yours.get(id))) {
                        names.merge(id, ONE_OF_TWO + mistake, (a, b) -> a + "\n" + b);
                    }
                });
            }
        }
        return names;
    }

    /**
     * Whether {@code a} and {@code b} together are {@code yours}: their failed tests together are
     * exactly yours, every one of yours fails as one of theirs does (or is failed by both, whose two
     * mistakes at once may give other numbers), and each of the two explains a failure the other does
     * not (else one alone would do).
     */
    private static boolean together(Map<String, String> yours, Map<String, String> a, Map<String, String> b) {
        if (a.isEmpty() || b.isEmpty()) {
            return false;
        }
        boolean aNeeded = false;
        boolean bNeeded = false;
        for (Map.Entry<String, String> failure : yours.entrySet()) {
            boolean asA = Objects.equals(a.get(failure.getKey()), failure.getValue());
            boolean asB = Objects.equals(b.get(failure.getKey()), failure.getValue());
            // A test both mistakes fail may fail otherwise: two mistakes at once change its numbers.
            boolean byBoth = a.containsKey(failure.getKey()) && b.containsKey(failure.getKey());
            if (!asA && !asB && !byBoth) {
                return false;
            }
            aNeeded |= asA && !asB;
            bNeeded |= asB && !asA;
        }
        return aNeeded && bNeeded && yours.keySet().containsAll(a.keySet()) && yours.keySet().containsAll(b.keySet());
    }

    /** The failure signature of a task's outcomes: failed regular unit tests by id, their numbers to six digits. */
    static Map<String, String> of(List<TestOutcome> outcomes) {
        Map<String, String> failed = new TreeMap<>();
        for (TestOutcome t : outcomes) {
            if (!t.passed() && !t.bonus() && !t.isRenderTest()) {
                failed.put(t.id(), withNumbersRounded(t.message()));
            }
        }
        return failed;
    }

    private static final Pattern NUMBER = Pattern.compile("-?\\d+(\\.\\d+)?([eE][-+]?\\d+)?");
    private static final Pattern OBJECT_ADDRESS = Pattern.compile("@[0-9a-f]{4,}");
    /** "ClampTexture.java:22" in a stack frame: where the student's file has its lines is no part of the mistake. */
    private static final Pattern SOURCE_LINE = Pattern.compile("(\\w+\\.java):\\d+");

    static String withNumbersRounded(String message) {
        String layoutFree = SOURCE_LINE.matcher(OBJECT_ADDRESS.matcher(message).replaceAll("@")).replaceAll("$1");
        Matcher m = NUMBER.matcher(layoutFree);
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            String rounded = new BigDecimal(m.group()).round(new MathContext(6)).stripTrailingZeros().toString();
            m.appendReplacement(out, Matcher.quoteReplacement(rounded));
        }
        m.appendTail(out);
        return out.toString();
    }
}
