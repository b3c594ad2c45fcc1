package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotEquals;

import java.util.List;
import java.util.Map;
import org.junit.Test;

/**
 * The unit-test signature a known mistake is named by: the failed regular unit tests of a task and
 * their messages' numbers to six significant digits. The same mistake written another way fails the
 * same tests with the same numbers; a different mistake does not; two mistakes in two files fail
 * the two mistakes' tests together. Whatever does not fit exactly names nothing.
 */
public class FailureSignaturesTest {
    private static TestOutcome outcome(String className, String method, boolean bonus, boolean passed, String message) {
        return new TestOutcome(className + "#" + method, className, method, 2, "Sphere", 1, bonus, "visible", passed, message, 0);
    }

    @Test
    public void theSignatureIsTheFailedRegularUnitTestsWithTheirMessages() {
        List<TestOutcome> outcomes = List.of(
                outcome("ray.surface.SphereTest", "a", false, false, "expected t = 2; your intersect returned t = 1.282202112918652"),
                outcome("ray.surface.SphereTest", "b", false, true, ""),
                outcome("ray.surface.SphereHardCasesBonusTest", "c", true, false, "bonus: a correct solution may fail this"),
                outcome("ray.endtoend.SphereRenderTest", "d", false, false, "does not look like the reference"));
        assertEquals(Map.of("ray.surface.SphereTest#a", "expected t = 2; your intersect returned t = 1.2822"),
                FailureSignatures.of(outcomes));
    }

    @Test
    public void numbersCountToSixSignificantDigitsAndObjectAddressesNotAtAll() {
        assertEquals("t = 0.36 and 0.000004 and -3 at ray.Foo@",
                FailureSignatures.withNumbersRounded("t = 0.35999999046325687 and 4.0000000001E-6 and -3 at ray.Foo@1b2c3d4e"));
        // Where a file has its lines is no part of a mistake.
        assertEquals("threw\n    at ray.shading.ClampTexture.getTexColor(ClampTexture.java)",
                FailureSignatures.withNumbersRounded("threw\n    at ray.shading.ClampTexture.getTexColor(ClampTexture.java:22)"));
        // A different number past the sixth digit is a different failure.
        assertNotEquals(FailureSignatures.withNumbersRounded("t = 1.2822021"), FailureSignatures.withNumbersRounded("t = 1.2823"));
        assertEquals(FailureSignatures.withNumbersRounded("t = 1.28220211"), FailureSignatures.withNumbersRounded("t = 1.2822021000000004"));
    }

    private static final Map<String, String> REPEAT_OFF = Map.of("RepeatTest#a", "returned texel (1, 1)", "HiddenTest#r", "texel (0, 1)");
    private static final Map<String, String> CLAMP_OFF = Map.of("ClampTest#a", "texel (4, 2) is outside", "HiddenTest#c", "threw");
    private static final Map<String, String> NO_HALF = Map.of("RepeatTest#a", "returned texel (0, 0)");

    private static Map<String, Map<String, String>> catalogue() {
        Map<String, Map<String, String>> theirs = new java.util.LinkedHashMap<>();
        theirs.put("rounds twice", REPEAT_OFF);
        theirs.put("clamps to W", CLAMP_OFF);
        theirs.put("drops the half", NO_HALF);
        return theirs;
    }

    @Test
    public void exactlyOneMistakesSignatureNamesItOnEveryFailure() {
        Map<String, String> names = FailureSignatures.named(REPEAT_OFF, catalogue());
        assertEquals(REPEAT_OFF.keySet(), names.keySet());
        names.values().forEach(name -> assertEquals(FailureSignatures.SAME_FAILURES + "rounds twice", name));
    }

    @Test
    public void twoMistakesTogetherAreEachNamedOnTheirOwnFailures() {
        Map<String, String> yours = new java.util.TreeMap<>(REPEAT_OFF);
        yours.putAll(CLAMP_OFF);
        Map<String, String> names = FailureSignatures.named(yours, catalogue());
        assertEquals(FailureSignatures.ONE_OF_TWO + "rounds twice", names.get("RepeatTest#a"));
        assertEquals(FailureSignatures.ONE_OF_TWO + "rounds twice", names.get("HiddenTest#r"));
        assertEquals(FailureSignatures.ONE_OF_TWO + "clamps to W", names.get("ClampTest#a"));
        assertEquals(FailureSignatures.ONE_OF_TWO + "clamps to W", names.get("HiddenTest#c"));
    }

    @Test
    public void aTestBothMistakesFailMayFailWithOtherNumbers() {
        Map<String, String> farRoot = Map.of("SphereTest#inside", "returned t = 3", "SphereTest#far", "returned t = 6");
        Map<String, String> unitD = Map.of("SphereTest#inside", "returned t = 1.5", "SphereTest#scaled", "returned t = 4");
        Map<String, Map<String, String>> theirs = new java.util.LinkedHashMap<>();
        theirs.put("far root", farRoot);
        theirs.put("unit d", unitD);
        Map<String, String> yours = Map.of("SphereTest#inside", "returned t = 7", "SphereTest#far", "returned t = 6",
                "SphereTest#scaled", "returned t = 4");
        Map<String, String> names = FailureSignatures.named(yours, theirs);
        assertEquals(FailureSignatures.ONE_OF_TWO + "far root", names.get("SphereTest#far"));
        assertEquals(FailureSignatures.ONE_OF_TWO + "unit d", names.get("SphereTest#scaled"));
        // The test both fail, with numbers of neither, is named by neither.
        assertEquals(null, names.get("SphereTest#inside"));
    }

    @Test
    public void anythingThatDoesNotFitExactlyNamesNothing() {
        // One more failure than the mistake's, another number, a failure of neither of a pair.
        Map<String, String> more = new java.util.TreeMap<>(REPEAT_OFF);
        more.put("RepeatTest#b", "returned texel (2, 0)");
        assertEquals(Map.of(), FailureSignatures.named(more, catalogue()));
        assertEquals(Map.of(), FailureSignatures.named(Map.of("RepeatTest#a", "returned texel (1, 1)", "HiddenTest#r", "texel (0, 2)"),
                catalogue()));
        Map<String, String> pairAndMore = new java.util.TreeMap<>(REPEAT_OFF);
        pairAndMore.putAll(CLAMP_OFF);
        pairAndMore.put("GroupTest#x", "expected a hit");
        assertEquals(Map.of(), FailureSignatures.named(pairAndMore, catalogue()));
        // Two mistakes with one signature cannot be told apart.
        Map<String, Map<String, String>> twins = catalogue();
        twins.put("another way to round twice", REPEAT_OFF);
        assertEquals(Map.of(), FailureSignatures.named(REPEAT_OFF, twins));
        // Nothing failed: nothing to name.
        assertEquals(Map.of(), FailureSignatures.named(Map.of(), catalogue()));
    }
}
