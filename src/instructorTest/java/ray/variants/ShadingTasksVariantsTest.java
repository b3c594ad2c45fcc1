package ray.variants;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.Test;
import ray.assignment.Assignment;

/**
 * The tasks the course-2017 preset gives and the default one leaves to the framework (the ray's
 * color and the light loops), written the ways students write them, earn every point of their task
 * and render every shipped scene within tolerance; the known mistakes lose points of their task. As
 * {@link AlternativeSolutionsTest}, under the course-2017 assignment, whose numbers the grader's
 * tasks then have.
 */
public class ShadingTasksVariantsTest {
    private static final String RENDER_TESTS = "ray.endtoend.";
    private static Assignment before;
    private static int task;
    private static int rayColor;
    private static Path work;
    /** What each variant passed and failed, in build/variants/lighting-summary.txt for the instructor to read. */
    private static final StringBuilder SUMMARY = new StringBuilder();

    @BeforeClass
    public static void underCourse2017() throws Exception {
        before = Assignment.current();
        Assignment.use(Assignment.preset("course-2017"));
        task = Assignment.current().number("lighting");
        rayColor = Assignment.current().number("ray-color");
        work = Files.createTempDirectory("ray1-lighting-variants");
    }

    @AfterClass
    public static void restore() throws Exception {
        Assignment.use(before);
        Path summary = Path.of("build/variants/shading-tasks-summary.txt");
        Files.createDirectories(summary.getParent());
        Files.writeString(summary, SUMMARY.toString());
        try (var files = Files.walk(work)) {
            files.sorted((a, b) -> b.compareTo(a)).forEach(p -> p.toFile().delete());
        }
    }

    /**
     * The lights in reverse order with the shadow test first, the shadow test after the formula for
     * every light, and the exponent as repeated products in a helper per light: each earns every
     * point and renders every scene.
     */
    @Test
    public void lightLoopsWrittenAnyCorrectWayEarnEveryPoint() throws Exception {
        StringBuilder unfair = new StringBuilder();
        for (String name : List.of("lighting-lights-reversed", "lighting-shadow-after-formula", "lighting-repeated-products")) {
            Variant variant = Variant.correct(name, task);
            List<VariantGrading.Outcome> outcomes = VariantGrading.run(variant,
                    (t, type) -> t == task || type.startsWith(RENDER_TESTS), work);
            summarize(variant, outcomes);
            assertTrue(variant + " ran no graded test", outcomes.stream().anyMatch(o -> o.task == task));
            assertTrue(variant + " ran no render test of another task", outcomes.stream().anyMatch(o -> o.task != task));
            outcomes.stream().filter(o -> !o.passed()).forEach(o -> unfair.append("\n  ").append(variant).append(": ").append(o));
        }
        assertTrue("correct light loops lost points:" + unfair, unfair.length() == 0);
    }

    /** No shadow test, l reversed, no 1/r², Phong's mirror-form highlight: each loses points of the lighting task. */
    @Test
    public void knownMistakesLosePointsOfTheLightingTask() throws Exception {
        List<String> report = new ArrayList<>();
        for (String name : List.of("lighting-no-shadow-test", "lighting-light-vector-reversed", "lighting-no-falloff",
                "lighting-mirror-form-specular")) {
            Variant wrong = Variant.wrong(name, task);
            List<VariantGrading.Outcome> outcomes = VariantGrading.run(wrong, (t, type) -> t == task, work);
            summarize(wrong, outcomes);
            List<String> lost = outcomes.stream().filter(o -> !o.passed()).map(o -> o.test).collect(Collectors.toList());
            report.add(name + ": " + lost);
            assertTrue(wrong + " must lose points of the lighting task, but passed all " + outcomes.size() + " of its tests",
                    !lost.isEmpty());
        }
        assertEquals(4, report.size());
    }

    /** The ray's color as one expression, and with the search on a copy of the ray: every point, every render. */
    @Test
    public void rayColorWrittenAnyCorrectWayEarnsEveryPoint() throws Exception {
        StringBuilder unfair = new StringBuilder();
        for (String name : List.of("ray-color-ternary", "ray-color-copied-ray")) {
            Variant variant = Variant.correct(name, rayColor);
            List<VariantGrading.Outcome> outcomes = VariantGrading.run(variant,
                    (t, type) -> t == rayColor || type.startsWith(RENDER_TESTS), work);
            summarize(variant, outcomes);
            assertTrue(variant + " ran no graded test", outcomes.stream().anyMatch(o -> o.task == rayColor));
            outcomes.stream().filter(o -> !o.passed()).forEach(o -> unfair.append("\n  ").append(variant).append(": ").append(o));
        }
        assertTrue("a correct ray color lost points:" + unfair, unfair.length() == 0);
    }

    /** Black for the background, the hit shaded one depth deeper: each loses points of the ray-color task. */
    @Test
    public void rayColorMistakesLosePointsOfTheirTask() throws Exception {
        for (String name : List.of("ray-color-black-background", "ray-color-depth-plus-one")) {
            Variant wrong = Variant.wrong(name, rayColor);
            List<VariantGrading.Outcome> outcomes = VariantGrading.run(wrong, (t, type) -> t == rayColor, work);
            summarize(wrong, outcomes);
            assertTrue(wrong + " must lose points of the ray-color task", outcomes.stream().anyMatch(o -> !o.bonus && !o.passed()));
        }
    }

    private static synchronized void summarize(Variant variant, List<VariantGrading.Outcome> outcomes) {
        long passed = outcomes.stream().filter(VariantGrading.Outcome::passed).count();
        SUMMARY.append(String.format("%-36s %-13s %3d of %3d tests passed%n", variant.name, variant.correct ? "correct" : "known wrong",
                passed, outcomes.size()));
        outcomes.stream().filter(o -> !o.passed()).forEach(o -> SUMMARY.append("    fails ").append(o.test).append('\n'));
    }
}
