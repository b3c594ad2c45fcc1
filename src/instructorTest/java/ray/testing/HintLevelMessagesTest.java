package ray.testing;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.util.Map;
import org.junit.After;
import org.junit.Test;
import ray.assignment.Assignment;
import ray.assignment.HintLevel;
import ray.image.Image;
import ray.math.Vec3;
import ray.shading.RepeatTexture;
import ray.shading.TextureLookupsAccess;
import ray.surface.HitMessages;

/**
 * Failure messages follow the task's hint level: at goal they say what was expected and what came
 * back, never a cause, a fix or a formula; at formulas they give all three; a task's own level wins
 * over the assignment's.
 */
public class HintLevelMessagesTest {
    private final Assignment before = Assignment.current();

    @After
    public void restore() {
        Assignment.use(before);
        Hints.running(null);
    }

    private static void at(String hints, String hintsOfSphere, String running) throws Exception {
        Map<String, String> keys = new java.util.LinkedHashMap<>(Assignment.overrides(null, hints));
        Assignment a = Assignment.resolve(java.nio.file.Path.of("."), "intersections", keys);
        if (hintsOfSphere != null) {
            java.nio.file.Path file = java.nio.file.Files.createTempFile("assignment", ".properties");
            java.nio.file.Files.writeString(file, "preset = intersections\nhints = " + hints + "\nhints.sphere = " + hintsOfSphere + "\n");
            a = Assignment.resolve(java.nio.file.Path.of("."), file.toString(), Map.of());
            java.nio.file.Files.delete(file);
        }
        Assignment.use(a);
        Hints.running(StudentTask.of(running));
    }

    private static String hitLine() {
        return HitMessages.line("the ray at the unit sphere", "a hit at t = 4", "your intersect returned t = 8",
                "that is the expected t times |d| = 2");
    }

    @Test
    public void atGoalAHitMessageSaysWhatCameBackAndNoCause() throws Exception {
        at("goal", null, "sphere");
        assertEquals(HintLevel.GOAL, Hints.level());
        assertEquals("the ray at the unit sphere: expected a hit at t = 4; your intersect returned t = 8", hitLine());
        assertEquals("", Hints.fix(": divide by the radius"));
        at("steps", null, "sphere");
        assertTrue(hitLine().endsWith("; that is the expected t times |d| = 2"));
        assertEquals(": divide by the radius", Hints.fix(": divide by the radius"));
    }

    @Test
    public void aTasksOwnLevelWins() throws Exception {
        at("formulas", "goal", "sphere");
        assertFalse(hitLine().contains("times |d|"));
        at("formulas", "goal", "triangle");
        assertTrue(hitLine().contains("times |d|"));
    }

    @Test
    public void aTextureMessageStatesTheConventionInWordsBelowFormulas() throws Exception {
        Image image = TextureLookupsAccess.distinctTexels(4, 3);
        RepeatTexture wrong = new RepeatTexture(image) {
            @Override
            public Vec3 getTexColor(double u, double v) {
                return TextureLookupsAccess.texel(4, 3, 1, 1);
            }
        };
        at("goal", null, "textures");
        String goal = failure(wrong);
        assertTrue(goal, goal.contains("the texel is the nearest one: column u·W and row (1 − v)·H counted from the top"));
        assertFalse(goal, goal.contains("(int)"));
        at("formulas", null, "textures");
        String formulas = failure(wrong);
        assertTrue(formulas, formulas.contains("(int)(u·W + 0.5)"));
    }

    private static String failure(RepeatTexture texture) {
        try {
            TextureLookupsAccess.assertTexel(texture, 4, 3, 0.0, 1.0, 0, 0);
        } catch (AssertionError e) {
            return e.getMessage();
        }
        fail("a wrong texel passed");
        return null;
    }
}
