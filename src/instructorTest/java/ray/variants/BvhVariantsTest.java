package ray.variants;

import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.Test;
import ray.assignment.Assignment;

/**
 * The bvh task written the ways students write it, under the preset that gives it
 * ({@code course-2019-part2}): a midpoint split, the surface area heuristic with searches on a stack
 * of their own, and the slab test written axis by axis with a branch for a zero direction earn every
 * point of the task, its bonus tests too; the known mistakes (a ray inside a box skipping it, the
 * ray's segment ignored, the textbook slab test, a strict interval, the children searched without
 * shortening the ray, a shadow search for the closest hit, the left child always first) each lose
 * regular points of it.
 */
public class BvhVariantsTest {
    private static Assignment before;
    private static int task;
    private static Path work;

    @BeforeClass
    public static void underPart2() throws Exception {
        before = Assignment.current();
        Assignment.use(Assignment.preset("course-2019-part2"));
        task = Assignment.current().number("bvh");
        work = Files.createTempDirectory("ray1-bvh-variants");
    }

    @AfterClass
    public static void restore() throws Exception {
        Assignment.use(before);
        try (var files = Files.walk(work)) {
            files.sorted((a, b) -> b.compareTo(a)).forEach(p -> p.toFile().delete());
        }
    }

    @Test
    public void treesAndSlabTestsWrittenAnyCorrectWayEarnEveryPoint() throws Exception {
        StringBuilder unfair = new StringBuilder();
        for (String name : List.of("bvh-midpoint", "bvh-sah", "bvh-slab-written-out")) {
            Variant variant = Variant.correct(name, task);
            List<VariantGrading.Outcome> outcomes = VariantGrading.run(variant, (t, type) -> t == task, work);
            assertTrue(variant + " ran no graded test", !outcomes.isEmpty());
            outcomes.stream().filter(o -> !o.passed()).forEach(o -> unfair.append("\n  ").append(variant).append(": ").append(o));
        }
        assertTrue("correct trees lost points:" + unfair, unfair.length() == 0);
    }

    @Test
    public void knownMistakesLosePointsOfTheirTask() throws Exception {
        for (String name : List.of("bvh-inside-skipped", "bvh-segment-ignored", "bvh-textbook-slab", "bvh-strict-slab",
                "bvh-far-first-unshortened", "bvh-any-closest", "bvh-left-first")) {
            Variant wrong = Variant.wrong(name, task);
            List<VariantGrading.Outcome> outcomes = VariantGrading.run(wrong, (t, type) -> t == task, work);
            assertTrue(wrong + " must lose regular points of its task: " + outcomes, outcomes.stream().anyMatch(o -> !o.bonus && !o.passed()));
        }
    }
}
