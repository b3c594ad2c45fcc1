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
 * The shading tasks the course presets give and the default one leaves to the framework (the ray's
 * color and the light loops under course-2017, the BRDFs under course-2019), written the ways
 * students write them, earn every point of their task and render every shipped scene within
 * tolerance; the known mistakes lose points of their task. As {@link AlternativeSolutionsTest},
 * under the preset that gives the task, whose numbers the grader's tasks then have.
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
        assertEachEarnsEveryPoint(List.of("lighting-lights-reversed", "lighting-shadow-after-formula", "lighting-repeated-products"), task,
                "correct light loops");
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
        assertEachEarnsEveryPoint(List.of("ray-color-ternary", "ray-color-copied-ray"), rayColor, "a correct ray color");
    }

    /** Black for the background, the hit shaded one depth deeper, no depth limit: each loses points of the ray-color task. */
    @Test
    public void rayColorMistakesLosePointsOfTheirTask() throws Exception {
        assertEachLosesPointsOfItsTask(List.of("ray-color-black-background", "ray-color-depth-plus-one", "ray-color-unbounded-depth"),
                rayColor);
    }

    /**
     * The 2019 BRDFs (course-2019's task): each channel over π on its own with the half vector by hand
     * and repeated products, 1/π as a constant with the diffuse part borrowed and an early return:
     * every point of the task and every render test.
     */
    @Test
    public void brdfsWrittenAnyCorrectWayEarnEveryPoint() throws Exception {
        Assignment.use(Assignment.preset("course-2019"));
        try {
            assertEachEarnsEveryPoint(List.of("brdfs-written-out", "brdfs-inverse-pi"), Assignment.current().number("brdfs"), "correct BRDFs");
        } finally {
            Assignment.use(Assignment.preset("course-2017"));
        }
    }

    /** No π, the highlight over π too, Phong's mirror form, the highlight without the cosine: each loses points of the BRDF task. */
    @Test
    public void brdfMistakesLosePointsOfTheirTask() throws Exception {
        Assignment.use(Assignment.preset("course-2019"));
        try {
            assertEachLosesPointsOfItsTask(List.of("brdfs-no-pi", "brdfs-specular-over-pi", "brdfs-mirror-form", "brdfs-cosine-removed"),
                    Assignment.current().number("brdfs"));
        } finally {
            Assignment.use(Assignment.preset("course-2017"));
        }
    }

    /**
     * The 2019 reflection shader: the lights in reverse with the shadow test after the share and the
     * reflection in a helper, and channel by channel with the shadow test first and Schlick as
     * products: every point and every render test.
     */
    @Test
    public void reflectionShadersWrittenAnyCorrectWayEarnEveryPoint() throws Exception {
        Assignment.use(Assignment.preset("course-2019"));
        try {
            assertEachEarnsEveryPoint(List.of("reflection-written-out", "reflection-vectors"), Assignment.current().number("reflection"),
                    "correct reflection shaders");
        } finally {
            Assignment.use(Assignment.preset("course-2017"));
        }
    }

    /** Schlick from the wrong side, a mirror ray where k_m = 0, no cosine, no back-face gate: each loses points of the reflection task. */
    @Test
    public void reflectionMistakesLosePointsOfTheirTask() throws Exception {
        Assignment.use(Assignment.preset("course-2019"));
        try {
            assertEachLosesPointsOfItsTask(List.of("reflection-r0-wrong-side", "reflection-mirror-at-zero", "reflection-no-cosine",
                    "reflection-no-gate"), Assignment.current().number("reflection"));
        } finally {
            Assignment.use(Assignment.preset("course-2017"));
        }
    }

    /**
     * The microfacet BRDFs, an extra-credit task (every test a bonus test): the textbook forms (tan²θ
     * from 1 − cos²θ, G1 through tanθ, the product 4|n·l||n·v|) pass every test but the hard cases,
     * where they divide by zero, as a textbook sphere misses only the sphere's; the Fresnel factor
     * as the mean of the s- and p-polarised reflectances, with D through 1/exp and G1 in a helper,
     * passes every test.
     */
    @Test
    public void microfacetBrdfsWrittenAnyCorrectWayEarnEveryPoint() throws Exception {
        Assignment.use(Assignment.preset("course-2019"));
        try {
            int number = Assignment.current().number("microfacet");
            StringBuilder unfair = new StringBuilder();
            for (String name : List.of("microfacet-textbook", "microfacet-polarised")) {
                Variant variant = Variant.correct(name, number);
                List<VariantGrading.Outcome> outcomes = VariantGrading.run(variant, (t, type) -> t == number, work);
                summarize(variant, outcomes);
                assertTrue(variant + " ran no graded test", outcomes.stream().anyMatch(o -> o.task == number));
                outcomes.stream().filter(o -> !o.passed() && !(name.equals("microfacet-textbook") && hardCase(o)))
                        .forEach(o -> unfair.append("\n  ").append(variant).append(": ").append(o));
            }
            assertTrue("correct microfacet BRDFs lost points:" + unfair, unfair.length() == 0);
        } finally {
            Assignment.use(Assignment.preset("course-2017"));
        }
    }

    /** A test of the hard cases, which only a form that never divides by zero passes: the bonus class and the hidden hard cases. */
    private static boolean hardCase(VariantGrading.Outcome outcome) {
        return outcome.test.contains("HardCases");
    }

    /** a = α tanθ, Schlick's Fresnel, π in the denominator, one masking term, α squared twice: each fails tests of its (extra-credit) task. */
    @Test
    public void microfacetMistakesFailTestsOfTheirTask() throws Exception {
        Assignment.use(Assignment.preset("course-2019"));
        try {
            int number = Assignment.current().number("microfacet");
            for (String name : List.of("microfacet-a-inverted", "microfacet-schlick", "microfacet-pi-denominator", "microfacet-one-masking",
                    "microfacet-alpha-squared-twice")) {
                Variant wrong = Variant.wrong(name, number);
                List<VariantGrading.Outcome> outcomes = VariantGrading.run(wrong, (t, type) -> t == number, work);
                summarize(wrong, outcomes);
                assertTrue(wrong + " must fail tests of its task", outcomes.stream().anyMatch(o -> !o.passed() && !hardCase(o)));
            }
        } finally {
            Assignment.use(Assignment.preset("course-2017"));
        }
    }

    /** Each correct variant named earns every point of task {@code number} and passes every render test, its task's and the others'. */
    private static void assertEachEarnsEveryPoint(List<String> names, int number, String what) throws Exception {
        StringBuilder unfair = new StringBuilder();
        for (String name : names) {
            Variant variant = Variant.correct(name, number);
            List<VariantGrading.Outcome> outcomes = VariantGrading.run(variant,
                    (t, type) -> t == number || type.startsWith(RENDER_TESTS), work);
            summarize(variant, outcomes);
            assertTrue(variant + " ran no graded test", outcomes.stream().anyMatch(o -> o.task == number));
            assertTrue(variant + " ran no render test of another task", outcomes.stream().anyMatch(o -> o.task != number));
            outcomes.stream().filter(o -> !o.passed()).forEach(o -> unfair.append("\n  ").append(variant).append(": ").append(o));
        }
        assertTrue(what + " lost points:" + unfair, unfair.length() == 0);
    }

    /** Each known mistake named fails some regular test of task {@code number}. */
    private static void assertEachLosesPointsOfItsTask(List<String> names, int number) throws Exception {
        for (String name : names) {
            Variant wrong = Variant.wrong(name, number);
            List<VariantGrading.Outcome> outcomes = VariantGrading.run(wrong, (t, type) -> t == number, work);
            summarize(wrong, outcomes);
            assertTrue(wrong + " must lose points of its task", outcomes.stream().anyMatch(o -> !o.bonus && !o.passed()));
        }
    }

    private static synchronized void summarize(Variant variant, List<VariantGrading.Outcome> outcomes) {
        long passed = outcomes.stream().filter(VariantGrading.Outcome::passed).count();
        SUMMARY.append(String.format("%-36s %-13s %3d of %3d tests passed%n", variant.name, variant.correct ? "correct" : "known wrong",
                passed, outcomes.size()));
        outcomes.stream().filter(o -> !o.passed()).forEach(o -> SUMMARY.append("    fails ").append(o.test).append('\n'));
    }
}
