package ray.variants;

import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * `ray1 trace` names the file whose code is wrong, by evidence, for mistakes that once sent the
 * student to another file: a Triangle that ignores the segment's end (the group, correct, is not
 * to blame), and a RepeatTexture one row off (not a mirrored row, which a texel of the same color
 * suggested when texels were matched by color).
 */
public class TraceBlameTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    /**
     * Pixel (94, 151) of mesh-flat is where a render test's message pointed: the group, asking the
     * mesh's triangles in turn with the ray shortened to the closest hit so far, gets a farther hit
     * from a triangle that ignores ray.end and keeps it.
     */
    @Test
    public void aTriangleThatIgnoresTheSegmentsEndIsBlamedNotTheGroup() throws Exception {
        String out = VariantTrace.of(Variant.wrong("triangle-ignores-segment", 3), folder.getRoot().toPath(), "scenes/mesh-flat.xml", 94, 151);
        assertTrue(out, out.contains("on the ray cut to"));
        assertTrue(out, out.contains("Does Triangle.intersect check ray.end? See TODO(Task 3)"));
        assertFalse(out, out.contains("the group must keep the closest hit"));
        assertFalse(out, out.contains("TODO(Task 4)"));
    }

    /** The solution's trace of the same pixel blames no one. */
    @Test
    public void theSolutionsTraceOfThatPixelBlamesNoOne() throws Exception {
        Path solution = folder.newFolder("solution").toPath();
        Files.createDirectories(solution.resolve("ray/surface"));
        Files.copy(Path.of("src/main/java/ray/surface/Triangle.java"), solution.resolve("ray/surface/Triangle.java"));
        String out = VariantTrace.of(Variant.written("solution-triangle", 3, solution), folder.newFolder("work").toPath(),
                "scenes/mesh-flat.xml", 94, 151);
        assertTrue(out, out.contains("✓ the nearest hit in the list above"));
        assertFalse(out, out.contains("on the ray cut to"));
    }

    /**
     * Pixel (215, 87) of eclipse is on the globe, a RepeatTexture written inline: the lookup
     * H − 1 − (int) (v·H + ½) reads row 91 for the course's 92, which the trace names by its index.
     */
    @Test
    public void aRepeatTextureOneRowOffIsNamedByItsRowNotAsAMirror() throws Exception {
        assertOneRowAbove("scenes/textured/eclipse.xml", 215, 87, 273, 92);
    }

    /** The same on the globe scene (its texture named in the scene): pixel (155, 128) reads row 111 for 112. */
    @Test
    public void onTheGlobeSceneTheRowOffLookupIsNamedByItsRowToo() throws Exception {
        assertOneRowAbove("scenes/textured/globe.xml", 155, 128, 252, 112);
    }

    /** The row-off lookup's trace of pixel (x, y): texel (column, row) of the 512×256 globe, read one row above. */
    private void assertOneRowAbove(String scene, int x, int y, int column, int row) throws Exception {
        String out = VariantTrace.of(Variant.wrong("texture-rows-flipped-after-rounding", 5), folder.getRoot().toPath(), scene, x, y);
        assertTrue(out, out.contains("texel        (" + column + ", " + row + ") of 512×256"));
        assertTrue(out, out.contains("that is texel (" + column + ", " + (row - 1) + "), one row above: flipping after the rounding,"
                + " H − 1 − (int) (v·H + ½), is one row off"));
        assertFalse(out, out.contains("mirrored row"));
        assertTrue(out, out.contains("See TODO(Task 5)"));
    }

    /**
     * A light loop without the 1/r² falloff: at pixel (160, 150) of lights-and-shadows, on the ground,
     * the trace puts the shader's own result for each light beside the formula's and marks the two
     * lights that differ; the light behind the ground adds nothing either way.
     */
    @Test
    public void aLightLoopWithoutTheFalloffIsShownBesideTheFormula() throws Exception {
        String out = VariantTrace.of(Variant.wrong("lighting-no-falloff", 0), folder.getRoot().toPath(), "scenes/lights-and-shadows.xml",
                160, 150);
        assertTrue(out, out.contains("adds         (39.2899, 32.7416, 24.3223)   ✗ not the formula's (0.953844, 0.79487, 0.590475)"));
        assertTrue(out, out.contains("adds         (3.75497, 6.25829, 11.6225)   ✗ not the formula's"));
        assertTrue(out, out.contains("adds         (0, 0, 0)\n"));
    }

    /** The solution's light loop agrees with the formula at every light of that pixel. */
    @Test
    public void theSolutionsLightLoopAgreesWithTheFormula() throws Exception {
        Path solution = folder.newFolder("solution-lighting").toPath();
        Files.createDirectories(solution.resolve("ray/shading"));
        for (String name : new String[] {"Lambertian.java", "Phong.java"}) {
            Files.copy(Path.of("src/main/java/ray/shading/" + name), solution.resolve("ray/shading/" + name));
        }
        String out = VariantTrace.of(Variant.written("solution-lighting", 0, solution), folder.newFolder("work-lighting").toPath(),
                "scenes/lights-and-shadows.xml", 160, 150);
        assertTrue(out, out.contains("adds         (0.953844, 0.79487, 0.590475)"));
        assertFalse(out, out.contains("not the formula's"));
    }

    /** A ray color that returns black on a miss: the trace's background beside the renderer's black pixel. */
    @Test
    public void aRayColorThatLosesTheBackgroundIsFlaggedAtThePixelValue() throws Exception {
        String out = VariantTrace.of(Variant.wrong("ray-color-black-background", 0), folder.getRoot().toPath(), "scenes/mirror-pair.xml", 5, 5);
        assertTrue(out, out.contains("none: the pixel shows the background color (0.35, 0.5, 0.75)"));
        assertTrue(out, out.contains("radiance     (0, 0, 0)"));
        assertTrue(out, out.contains("the trace computed (0.35, 0.5, 0.75) for the center ray; the renderer's value above is the one in the image"));
    }

    /**
     * A 2019 reflection shader without the cosine: at pixel (100, 140) of mirror-spheres, on the left
     * sphere, the first light falls at n·l = 0.625954, so the shader's share is the formula's over it;
     * the mirror term is traced as the renderer does.
     */
    @Test
    public void aReflectionShaderWithoutTheCosineIsShownBesideTheFormula() throws Exception {
        String out = VariantTrace.of(Variant.wrong("reflection-no-cosine", 0), folder.getRoot().toPath(), "scenes-2019/mirror-spheres.xml",
                100, 140, new String[] {"--course", "2019"});
        assertTrue(out, out.contains("✗ not the formula's (0.0176514, 0.0173572, 0.0161804)"));
        assertTrue(out, out.contains("R            (0.8, 0.8, 0.8)"));
    }
}
