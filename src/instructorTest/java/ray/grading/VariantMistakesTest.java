package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotEquals;

import java.util.List;
import java.util.Map;
import org.junit.Test;

/**
 * The unit-test signature a known mistake is named by: the failed regular unit tests of a task and
 * their messages' numbers to six significant digits. The same mistake written another way fails the
 * same tests with the same numbers; a different mistake, or a second one beside it, does not.
 */
public class VariantMistakesTest {
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
                VariantMistakes.failedUnitTests(outcomes));
    }

    @Test
    public void numbersCountToSixSignificantDigitsAndObjectAddressesNotAtAll() {
        assertEquals("t = 0.36 and 0.000004 and -3 at ray.Foo@",
                VariantMistakes.withNumbersRounded("t = 0.35999999046325687 and 4.0000000001E-6 and -3 at ray.Foo@1b2c3d4e"));
        // A different number past the sixth digit is a different failure.
        assertNotEquals(VariantMistakes.withNumbersRounded("t = 1.2822021"), VariantMistakes.withNumbersRounded("t = 1.2823"));
        assertEquals(VariantMistakes.withNumbersRounded("t = 1.28220211"), VariantMistakes.withNumbersRounded("t = 1.2822021000000004"));
    }
}
