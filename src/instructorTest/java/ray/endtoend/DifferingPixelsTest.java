package ray.endtoend;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Map;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.Test;
import ray.image.ImageDiff;
import ray.image.PngWriter;
import ray.render.PixelKinds;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.render.SphereAndTriangle;
import ray.surface.SurfaceKind;
import ray.scene.Scene;

/**
 * {@link DifferingPixels}: the render test's words for where a render differs, on
 * {@link SphereAndTriangle}, whose pixels are counted by hand: wrong triangles make it differ on
 * exactly the pixels they drew (triangles) or failed to draw (the background, in that render), and
 * the worst pixel is ImageDiff's, with the command that explains it.
 */
public class DifferingPixelsTest {
    private static final Path SCENE = Path.of("scenes", "sphere-and-triangle.xml");

    /** The solution's render, the reference. */
    private static final BufferedImage REFERENCE = eightBit(SphereAndTriangle.scene(), new Renderer(SphereAndTriangle.scene(), 1, 2).render());

    private static BufferedImage eightBit(Scene scene, RenderResult result) {
        return PngWriter.toBufferedImage(result.image, scene.getExposure());
    }

    /** The render of a variant, as the render test makes it. */
    private static RenderScenes.Rendered render(SphereAndTriangle.TriangleMaker triangle) {
        return RenderScenes.renderWithKinds(SphereAndTriangle.scene(triangle));
    }

    @Test
    public void aTriangleWithTheWrongNormalDiffersOnTrianglesOnly() {
        RenderScenes.Rendered yours = render(SphereAndTriangle.NormalFlipped::new);
        ImageDiff.Result result = ImageDiff.compare(REFERENCE, yours.image());
        int n = SphereAndTriangle.TRIANGLE_PIXELS;
        assertEquals(n, result.differingPixels());
        assertEquals("36 pixels differ; 36 of them are on triangles (Task 3)", DifferingPixels.onKinds(result, yours.kinds()));
        // Right under the light: 224 in the reference, black in yours.
        assertEquals(new ImageDiff.Pixel(11, 4), result.worstPixel());
        assertEquals(224, result.maxDifference());
        assertEquals(".\n    36 pixels differ; 36 of them are on triangles (Task 3)"
                + ".\n    The worst pixel is (11, 4): see how your code lit it with `ray1 trace " + SCENE + " 11 4`"
                + " (or explore it with `ray1 explore " + SCENE + "`)", DifferingPixels.sentences(result, yours.kinds(), SCENE));
    }

    /** Where the triangle is missing, your render shows the background, and that is what the sentence names. */
    @Test
    public void aTriangleWithAPartMissingDiffersOnTheBackgroundItLeaves() {
        RenderScenes.Rendered yours = render(SphereAndTriangle.HalfMissing::new);
        ImageDiff.Result result = ImageDiff.compare(REFERENCE, yours.image());
        assertEquals(SphereAndTriangle.TRIANGLE_PIXELS_BETA_ABOVE_HALF, result.differingPixels());
        assertEquals("10 pixels differ; 10 of them are on the background", DifferingPixels.onKinds(result, yours.kinds()));
        // The background's blue is furthest from the dimmest pixel lost, the far corner (8.5, −3.5): r² = 69.
        assertEquals(new ImageDiff.Pixel(18, 8), result.worstPixel());
        assertTrue(DifferingPixels.worstPixel(result, SCENE).startsWith("The worst pixel is (18, 8): see how your code lit it with `ray1 trace "
                + SCENE + " 18 8`"));
    }

    @Test
    public void bothMistakesNameBothKindsTheLargerFirst() {
        RenderScenes.Rendered yours = render(SphereAndTriangle.HalfMissingNormalFlipped::new);
        ImageDiff.Result result = ImageDiff.compare(REFERENCE, yours.image());
        assertEquals("36 pixels differ; 26 of them are on triangles (Task 3), 10 on the background",
                DifferingPixels.onKinds(result, yours.kinds()));
        assertEquals(new ImageDiff.Pixel(11, 4), result.worstPixel());
    }

    /** The render test's image is the plain render's, pixel for pixel. */
    @Test
    public void theRenderTestsImageIsThePlainRenders() {
        Scene scene = SphereAndTriangle.scene(SphereAndTriangle.HalfMissingNormalFlipped::new);
        BufferedImage plain = RenderScenes.render(scene);
        BufferedImage withKinds = RenderScenes.renderWithKinds(scene).image();
        assertEquals(0, ImageDiff.compare(plain, withKinds, 0, 0).maxDifference());
    }

    /**
     * Differences painted onto chosen pixels of the solution's render, whose kinds are known: every
     * kind present is named, the most first, ties in SurfaceKind's order, one pixel in the singular,
     * and the counts add up to the differing pixels whatever is chosen.
     */
    @Test
    public void theCountsAddUpAndReadInOrder() {
        RenderScenes.Rendered solution = RenderScenes.renderWithKinds(SphereAndTriangle.scene());
        PixelKinds kinds = solution.kinds();
        // (4, 4) sphere, (11, 4) and (12, 4) triangle, (0, 0) background.
        assertEquals("1 pixel differs, on the background", DifferingPixels.onKinds(paint(solution.image(), kinds, 0, 0), kinds));
        assertEquals("2 pixels differ; 1 of them is on a sphere (Task 2), 1 on a triangle (Task 3)",
                DifferingPixels.onKinds(paint(solution.image(), kinds, 11, 4, 4, 4), kinds));
        assertEquals("4 pixels differ; 2 of them are on triangles (Task 3), 1 on a sphere (Task 2), 1 on the background",
                DifferingPixels.onKinds(paint(solution.image(), kinds, 0, 0, 11, 4, 4, 4, 12, 4), kinds));

        Random random = new Random(7);
        Pattern count = Pattern.compile("(\\d+) (?:of them (?:is|are) )?on ");
        for (int round = 0; round < 20; round++) {
            BufferedImage changed = copy(solution.image());
            for (int k = random.nextInt(60) + 2; k > 0; k--) {
                changed.setRGB(random.nextInt(SphereAndTriangle.WIDTH), random.nextInt(SphereAndTriangle.HEIGHT), 0xffffff);
            }
            ImageDiff.Result result = ImageDiff.compare(solution.image(), changed);
            Map<SurfaceKind, Integer> counts = DifferingPixels.counts(result, kinds);
            assertEquals(result.differingPixels(), counts.values().stream().mapToInt(Integer::intValue).sum());
            String sentence = DifferingPixels.onKinds(result, kinds);
            assertTrue(sentence, sentence.startsWith(result.differingPixels() + " pixels differ; "));
            Matcher m = count.matcher(sentence.substring(sentence.indexOf(';')));
            int sum = 0;
            int previous = Integer.MAX_VALUE;
            int groups = 0;
            while (m.find()) {
                int n = Integer.parseInt(m.group(1));
                assertTrue(sentence + ": largest first", n <= previous);
                previous = n;
                sum += n;
                groups++;
            }
            assertEquals(sentence, result.differingPixels(), sum);
            assertEquals(sentence, counts.size(), groups);
            // The worst pixel named is ImageDiff's, which is the first of the most different in reading order.
            ImageDiff.Pixel worst = result.worstPixel();
            assertEquals(result.maxDifference(), result.differenceAt(worst.x(), worst.y()));
            assertTrue(DifferingPixels.worstPixel(result, SCENE).contains(" " + worst.x() + " " + worst.y() + "`"));
        }
    }

    @Test
    public void nothingIsSaidWhenTheSizesDifferAndTheWorstPixelAloneWithoutKinds() {
        BufferedImage other = new BufferedImage(SphereAndTriangle.WIDTH + 1, SphereAndTriangle.HEIGHT, BufferedImage.TYPE_INT_RGB);
        assertEquals("", DifferingPixels.sentences(ImageDiff.compare(REFERENCE, other), null, SCENE));
        assertEquals("", DifferingPixels.sentences(ImageDiff.compare(REFERENCE, copy(REFERENCE)), null, SCENE));
        ImageDiff.Result result = ImageDiff.compare(REFERENCE, render(SphereAndTriangle.NormalFlipped::new).image());
        assertEquals(".\n    " + DifferingPixels.worstPixel(result, SCENE), DifferingPixels.sentences(result, null, SCENE));
    }

    /** The solution's render with each pixel (x, y) of {@code xy} made to differ, compared with the solution's. */
    private static ImageDiff.Result paint(BufferedImage image, PixelKinds kinds, int... xy) {
        BufferedImage changed = copy(image);
        for (int k = 0; k < xy.length; k += 2) {
            changed.setRGB(xy[k], xy[k + 1], changed.getRGB(xy[k], xy[k + 1]) ^ 0x808080);
        }
        assertEquals(SurfaceKind.SPHERE, kinds.at(4, 4));
        assertEquals(SurfaceKind.TRIANGLE, kinds.at(12, 4));
        return ImageDiff.compare(image, changed);
    }

    private static BufferedImage copy(BufferedImage image) {
        BufferedImage out = new BufferedImage(image.getWidth(), image.getHeight(), BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                out.setRGB(x, y, image.getRGB(x, y));
            }
        }
        return out;
    }
}
