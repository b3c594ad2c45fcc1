package ray.variants;

import static org.junit.Assert.assertTrue;

import java.util.List;
import java.util.regex.Pattern;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * A student can only fix a bug from the numbers their code produced, so the graded tests' failures
 * must show them. Known-wrong variants are graded as a student's files would be, and the messages
 * of the tests they fail must give what their intersect returned (t, and β and γ for a triangle),
 * and name a cause only where the numbers identify it.
 */
public class FailureMessagesTest {
    @ClassRule
    public static final TemporaryFolder WORK = new TemporaryFolder();

    /** A number as the messages print one: "3", "-0.5", "5.267949192431123", "4.0E-6". */
    private static final String NUMBER = "-?[0-9]+(\\.[0-9]+)?(E-?[0-9]+)?";

    @Test
    public void aSphereThatTakesTheFarRootIsShownItsTAndTheFarRoot() throws Exception {
        String failure = failureOf(Variant.wrong("sphere-far-root", 2), "ray.surface.SphereTest#nonUnitDirectionScalesT");
        // (0,0,5) + t·(0,0,−2) enters the unit sphere at t = 2 and leaves at t = 3.
        assertTrue("the failure must give the expected and the returned t: " + failure,
                failure.contains("expected a hit at t = 2; your intersect returned t = 3"));
        assertTrue("the failure must name the far root: " + failure, failure.contains("far root"));
        assertTrue("normalizing is a correct choice, not this variant's bug, so the failure must not hint at it: " + failure,
                !failure.contains("normaliz"));
    }

    @Test
    public void aTriangleWithoutTheSumCheckIsShownTBetaAndGammaOfItsHit() throws Exception {
        // (2, 1 + 1e-9) is just past the edge v1–v2: β ≈ 0.5, γ ≈ 0.5 + 5e-10, so β + γ > 1.
        String failure = failureOf(Variant.wrong("triangle-no-sum-check", 3), "ray.surface.TriangleTest#justOutsideEdgeV1V2Misses");
        Pattern returned = Pattern.compile("expected a miss; your intersect returned true with t = " + NUMBER + " \\(β = " + NUMBER
                + ", γ = " + NUMBER + "\\)");
        assertTrue("the failure must give the t, β and γ the variant returned: " + failure, returned.matcher(failure).find());
        assertTrue("the failure must say that β + γ is over 1: " + failure,
                Pattern.compile("β \\+ γ = " + NUMBER + " > 1").matcher(failure).find());
    }

    @Test
    public void everyIntersectionFailureOfTheWrongSphereShowsWhatItReturned() throws Exception {
        Variant wrong = Variant.wrong("sphere-far-root", 2);
        List<VariantGrading.Outcome> outcomes = VariantGrading.run(wrong, (task, type) -> task == wrong.task, WORK.getRoot().toPath());
        StringBuilder silent = new StringBuilder();
        for (VariantGrading.Outcome o : outcomes) {
            // Sphere tests of this kind: the hand-computed, random and hidden ones (the bonus cases word their own summaries).
            boolean intersectionTest = o.test.startsWith("ray.surface.Sphere") || o.test.startsWith("ray.hidden.Task2");
            if (!o.passed() && !o.bonus && intersectionTest && !Pattern.compile("returned (true with )?t = " + NUMBER).matcher(o.failure).find()) {
                silent.append("\n  ").append(o);
            }
        }
        assertTrue("failures of " + wrong + " that do not show the returned t:" + silent, silent.length() == 0);
    }

    /**
     * A group that searches its own segment (1e-3, ∞) finds the plane the caller's segment (1.6, 10)
     * leaves out, and a hit outside (0, 3.5): both failures say that t lies outside the segment and
     * that a group searches the caller's.
     */
    @Test
    public void aGroupWithItsOwnSegmentIsToldToSearchTheCallers() throws Exception {
        Variant wrong = Variant.wrong("group-own-segment", 4);
        for (String[] c : new String[][] {{"ray.hidden.GroupHiddenTest#childrenSeeTheCallersOriginAndDirection",
                "your intersect returned t = 1.5; t = 1.5 is not inside the ray's segment (1.6, 10)"},
                {"ray.surface.GroupTest#groupWhoseChildrenAllMissLeavesTheRecordUntouched",
                        "your intersect returned true with t = 4; t = 4 is not inside the ray's segment (0, 3.5)"}}) {
            String failure = failureOf(wrong, c[0]);
            assertTrue(c[0] + " must give t and the segment: " + failure, failure.contains(c[1]));
            assertTrue(c[0] + " must name the caller's segment: " + failure, failure.contains("a group searches the caller's segment"));
        }
    }

    /** A group that returns whether its last child was hit reports a miss with the closest hit in the record: the message says so. */
    @Test
    public void aGroupThatReturnsTheLastChildsAnswerIsToldSo() throws Exception {
        String failure = failureOf(Variant.wrong("group-last-hit", 4), "ray.surface.GroupTest#closestHitWinsInEveryOrderOfTheChildren");
        assertTrue(failure, failure.contains("expected a hit at t = 4; your intersect returned false; it returned false, yet wrote a hit"
                + " into the record (t = 4, surface near (hit at t = 4.0)): a group returns whether any child was hit; does yours return whether the"
                + " last child it tried was?"));
    }

    /** A camera in float fails the hidden 1e-12 checks by some 1e-8: each failure names float precision. */
    @Test
    public void aFloatCameraIsToldOfFloatPrecision() throws Exception {
        Variant wrong = Variant.wrong("camera-float-casts", 1);
        List<VariantGrading.Outcome> failed = VariantGrading.run(wrong, (task, type) -> task == wrong.task, WORK.getRoot().toPath())
                .stream().filter(o -> !o.passed()).collect(java.util.stream.Collectors.toList());
        assertTrue(wrong + " must fail some test", !failed.isEmpty());
        for (VariantGrading.Outcome o : failed) {
            assertTrue(o.toString(), Pattern.compile("\\[off by some 1e-[6-9], about float precision").matcher(o.failure).find());
        }
    }

    /** The failure message of {@code test} when {@code variant} is graded on its task; the test must fail. */
    private static String failureOf(Variant variant, String test) throws Exception {
        List<VariantGrading.Outcome> outcomes = VariantGrading.run(variant, (task, type) -> task == variant.task, WORK.getRoot().toPath());
        VariantGrading.Outcome outcome = outcomes.stream().filter(o -> o.test.equals(test)).findFirst()
                .orElseThrow(() -> new AssertionError(test + " did not run for " + variant));
        assertTrue(variant + " must fail " + test, !outcome.passed());
        return outcome.failure;
    }
}
