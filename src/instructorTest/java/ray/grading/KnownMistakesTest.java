package ray.grading;

import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import org.junit.Test;
import ray.image.PngReader;

/**
 * A render that is the reference flipped or mirrored gets that mistake named; the reference itself,
 * and a render wrong in another way, get no name. On a shipped reference, so the images are real.
 */
public class KnownMistakesTest {
    private static BufferedImage reference() throws Exception {
        return PngReader.read(Path.of("scenes/reference/two-boxes.png"));
    }

    @Test
    public void anUpsideDownRenderIsNamed() throws Exception {
        String advice = KnownMistakes.of(KnownMistakes.flippedVertically(reference()), reference());
        assertTrue(advice, advice != null && advice.startsWith("Your image matches the reference flipped upside down"));
    }

    @Test
    public void aMirroredRenderIsNamed() throws Exception {
        String advice = KnownMistakes.of(KnownMistakes.flippedHorizontally(reference()), reference());
        assertTrue(advice, advice != null && advice.startsWith("Your image matches the reference mirrored left to right"));
    }

    @Test
    public void aCorrectRenderAndAnUnknownMistakeGetNoName() throws Exception {
        assertNull(KnownMistakes.of(reference(), reference()));
        BufferedImage dark = new BufferedImage(reference().getWidth(), reference().getHeight(), BufferedImage.TYPE_INT_RGB);
        assertNull(KnownMistakes.of(dark, reference()));
    }
}
