package ray.variants;

import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.Test;

/**
 * The grader is fair to every correct student: each task's files written the ways students write
 * them (the lecture's forms, the textbook's, Ray Tracing in One Weekend's idioms, normalized or
 * not; the sources are in {@code src/instructorTest/variants}) earn every regular point of their
 * task and render every shipped scene within the render tests' tolerance, while known-wrong
 * versions lose points in their task. A wrong version cannot cost points elsewhere: the grader
 * runs each task's tests with only that task's files taken from the submission (GraderTest).
 *
 * <p>Each variant runs in this JVM with its own copy of every project class
 * ({@link VariantGrading}); correct ones run their task's graded tests and every render test.
 */
public class AlternativeSolutionsTest {
    private static final String RENDER_TESTS = "ray.endtoend.";
    private static Path work;
    /** One line per variant graded, written to build/variants/summary.txt for the instructor to read. */
    private static final StringBuilder SUMMARY = new StringBuilder();

    @BeforeClass
    public static void makeWorkFolder() throws Exception {
        work = Files.createTempDirectory("ray1-variants");
    }

    @AfterClass
    public static void removeWorkFolder() throws Exception {
        Path summary = Path.of("build/variants/summary.txt");
        Files.createDirectories(summary.getParent());
        Files.writeString(summary, SUMMARY.toString());
        if (work != null) {
            try (var files = Files.walk(work)) {
                files.sorted((a, b) -> b.compareTo(a)).forEach(p -> p.toFile().delete());
            }
        }
    }

    @Test
    public void cameraRaysWrittenAnyCorrectWayEarnEveryPoint() throws Exception {
        assertEveryPoint(Variant.correct("camera-normalized", 1), Variant.correct("camera-lower-left", 1),
                Variant.correct("camera-scaled", 1), Variant.correct("camera-terms-reordered", 1));
    }

    @Test
    public void spheresWrittenAnyCorrectWayEarnEveryPoint() throws Exception {
        assertEveryPoint(Variant.correct("sphere-geometric", 2), Variant.correct("sphere-textbook", 2),
                Variant.correct("sphere-half-b", 2), Variant.correct("sphere-temp-record", 2));
    }

    @Test
    public void trianglesWrittenAnyCorrectWayEarnEveryPoint() throws Exception {
        assertEveryPoint(Variant.correct("triangle-cramer", 3), Variant.correct("triangle-moller-trumbore", 3),
                Variant.correct("triangle-areas", 3), Variant.correct("triangle-triple-products", 3));
    }

    @Test
    public void groupsWrittenAnyCorrectWayEarnEveryPoint() throws Exception {
        assertEveryPoint(Variant.correct("group-temp-record", 4), Variant.correct("group-fresh-record", 4),
                Variant.correct("group-compare-t", 4), Variant.correct("group-index-loop", 4));
    }

    @Test
    public void textureLookupsWrittenAnyCorrectWayEarnEveryPoint() throws Exception {
        assertEveryPoint(Variant.correct("texture-modulo", 5), Variant.correct("texture-wrap-first", 5),
                Variant.correct("texture-if-chains", 5), Variant.correct("texture-round", 5),
                Variant.correct("texture-image-rows", 5));
    }

    /**
     * The cylinder is extra credit, so all its tests are bonus tests: a correct cylinder must pass
     * every one of them (the regular-points rule above would hold vacuously), and a wrong one must
     * fail some.
     */
    @Test
    public void cylindersWrittenAnyCorrectWayEarnEveryBonusPoint() throws Exception {
        StringBuilder unfair = new StringBuilder();
        for (Variant variant : List.of(Variant.correct("cylinder-textbook", 6), Variant.correct("cylinder-unit-direction", 6))) {
            List<VariantGrading.Outcome> outcomes = VariantGrading.run(variant, (task, type) -> task == variant.task, work);
            assertTrue(variant + " ran no test of its task", !outcomes.isEmpty());
            summarize(variant, outcomes);
            outcomes.stream().filter(o -> !o.passed()).forEach(o -> unfair.append("\n  ").append(variant).append(": ").append(o));
        }
        assertTrue("a correct cylinder failed extra-credit tests:" + unfair, unfair.length() == 0);
        Variant wrong = Variant.wrong("cylinder-infinite-side", 6);
        List<VariantGrading.Outcome> outcomes = VariantGrading.run(wrong, (task, type) -> task == wrong.task, work);
        summarize(wrong, outcomes);
        assertTrue(wrong + " must fail some of its extra-credit tests", outcomes.stream().anyMatch(o -> !o.passed()));
    }

    @Test
    public void knownMistakesLosePointsInTheirOwnTask() throws Exception {
        for (Variant wrong : List.of(Variant.wrong("camera-flipped-v", 1), Variant.wrong("camera-uncentered", 1),
                Variant.wrong("sphere-far-root", 2), Variant.wrong("sphere-normal-inward", 2),
                Variant.wrong("sphere-normal-unnormalized", 2),
                Variant.wrong("sphere-unit-direction-assumed", 2), Variant.wrong("triangle-no-sum-check", 3),
                Variant.wrong("group-first-hit", 4), Variant.wrong("texture-no-half", 5),
                Variant.wrong("texture-rows-flipped-after-rounding", 5), Variant.wrong("texture-rows-not-flipped", 5),
                Variant.wrong("texture-round-then-flip", 5), Variant.wrong("texture-clamp-to-width", 5))) {
            List<VariantGrading.Outcome> outcomes = VariantGrading.run(wrong, (task, type) -> task == wrong.task, work);
            assertTrue(wrong + " ran no test of its task", !outcomes.isEmpty());
            List<VariantGrading.Outcome> lost = outcomes.stream().filter(o -> !o.bonus && !o.passed()).collect(Collectors.toList());
            summarize(wrong, outcomes);
            assertTrue(wrong + " must lose regular points of Task " + wrong.task + ", but passed all "
                    + outcomes.size() + " of its tests", !lost.isEmpty());
        }
    }

    /**
     * The mistakes of a real student's attempt at the course's Ray 1, written as variants: a sphere
     * and a triangle that ignore the ray's segment, a group that returns whether its last child was
     * hit, a group that searches its own segment, a camera in float, a lookup that rounds twice.
     * Each must cost points in its own task (the float camera only in the hidden tests' 1e-12).
     */
    @Test
    public void mistakesOfARealAttemptLosePointsInTheirOwnTask() throws Exception {
        for (Variant wrong : List.of(Variant.wrong("sphere-ignores-segment", 2), Variant.wrong("triangle-ignores-segment", 3),
                Variant.wrong("group-last-hit", 4), Variant.wrong("group-own-segment", 4), Variant.wrong("camera-float-casts", 1),
                Variant.wrong("texture-round-twice", 5))) {
            List<VariantGrading.Outcome> outcomes = VariantGrading.run(wrong, (task, type) -> task == wrong.task, work);
            assertTrue(wrong + " ran no test of its task", !outcomes.isEmpty());
            List<VariantGrading.Outcome> lost = outcomes.stream().filter(o -> !o.bonus && !o.passed()).collect(Collectors.toList());
            summarize(wrong, outcomes);
            assertTrue(wrong + " must lose regular points of Task " + wrong.task + ", but passed all "
                    + outcomes.size() + " of its tests", !lost.isEmpty());
        }
    }

    /**
     * Rounding v·H + 0.5 down and then flipping to H − j picks the nearest texel everywhere except
     * exactly on an edge between rows, so it must lose the tests on texel edges and nothing else: a
     * rule stated to the last tie costs only the tests about the tie.
     */
    @Test
    public void roundingBeforeTheFlipLosesOnlyTheTexelEdgeTests() throws Exception {
        Variant variant = Variant.wrong("texture-floor-then-flip", 5);
        List<VariantGrading.Outcome> outcomes = VariantGrading.run(variant,
                (task, type) -> task == variant.task || type.startsWith(RENDER_TESTS), work);
        summarize(variant, outcomes);
        List<String> failed = outcomes.stream().filter(o -> !o.passed()).map(o -> o.test).sorted().collect(Collectors.toList());
        assertTrue(String.valueOf(failed), failed.equals(List.of("ray.hidden.TexturesHiddenTest#coordinatesOnTexelEdgesRoundAsTheCourseDoes",
                "ray.shading.ClampTextureTest#onATexelEdgeTheCourseFlipsVBeforeRounding",
                "ray.shading.RepeatTextureTest#onATexelEdgeTheCourseFlipsVBeforeRounding")));
    }

    private static void assertEveryPoint(Variant... variants) throws Exception {
        StringBuilder unfair = new StringBuilder();
        for (Variant variant : variants) {
            List<VariantGrading.Outcome> outcomes = VariantGrading.run(variant,
                    (task, type) -> task == variant.task || type.startsWith(RENDER_TESTS), work);
            assertTrue(variant + " ran no graded test", outcomes.stream().anyMatch(o -> o.task == variant.task));
            assertTrue(variant + " ran no render test", outcomes.stream().anyMatch(o -> o.test.startsWith(RENDER_TESTS)));
            summarize(variant, outcomes);
            for (VariantGrading.Outcome o : outcomes) {
                if (!o.bonus && !o.passed()) {
                    unfair.append("\n  ").append(variant).append(" loses ").append(o.points).append(" points: ").append(o);
                }
            }
        }
        assertTrue("correct code lost points:" + unfair, unfair.length() == 0);
    }

    private static synchronized void summarize(Variant variant, List<VariantGrading.Outcome> outcomes) {
        double earned = 0;
        double regular = 0;
        int bonusPassed = 0;
        int bonus = 0;
        for (VariantGrading.Outcome o : outcomes) {
            if (o.bonus) {
                bonus++;
                bonusPassed += o.passed() ? 1 : 0;
            } else {
                regular += o.points;
                earned += o.passed() ? o.points : 0;
            }
        }
        SUMMARY.append(String.format("%-36s %-13s %3d tests, %5.1f of %5.1f regular points, bonus %d of %d%n", variant.name,
                variant.correct ? "correct" : "known wrong", outcomes.size(), earned, regular, bonusPassed, bonus));
        // Which tests it failed, so that a mistake's cost can be read test by test.
        outcomes.stream().filter(o -> !o.passed())
                .forEach(o -> SUMMARY.append(String.format("    fails %s (%s points)%n", o.test, o.points)));
    }
}
