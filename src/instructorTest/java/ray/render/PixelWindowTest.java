package ray.render;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.util.ArrayList;
import java.util.List;
import org.junit.Test;
import ray.scene.Scene;

/**
 * A window of the image is rendered with exactly the camera rays its pixels get in a whole-image
 * render (the accuracy report measures windows and relies on this), and "X,Y,W,H" parses with Y
 * counted from the top, as in the PNG file.
 */
public class PixelWindowTest {
    private static final int WIDTH = 9;
    private static final int HEIGHT = 6;

    /** The image points asked for, in the order a one-thread render asks: rows from the bottom, columns left to right. */
    private static List<double[]> asked(RenderPlan plan) {
        RecordingCamera camera = (RecordingCamera) plan.scene().getCamera();
        camera.asked.clear();
        new Renderer(plan, 1).render();
        return new ArrayList<>(camera.asked);
    }

    private static Scene scene() {
        Scene scene = TestScenes.scene(new RecordingCamera(), WIDTH, HEIGHT);
        scene.complete();
        return scene;
    }

    @Test
    public void aWindowAsksForTheSameImagePointsAsTheWholeImageDoesForThosePixels() {
        Scene scene = scene();
        for (SamplePattern pattern : new SamplePattern[] {SamplePattern.GRID, SamplePattern.jittered(7)}) {
            RenderPlan whole = RenderPlan.of(scene, 4, pattern);
            List<double[]> all = asked(whole);
            // Columns 2..5 and file rows 1..3 (from the top): renderer rows (from the bottom) 2..4.
            PixelWindow window = new PixelWindow(2, 1, 4, 3);
            List<double[]> part = asked(whole.withWindow(window));
            assertEquals(4 * 3 * 4, part.size());
            int k = 0;
            for (int j = HEIGHT - 1 - 3; j <= HEIGHT - 1 - 1; j++) {
                for (int i = 2; i <= 5; i++) {
                    for (int s = 0; s < 4; s++) {
                        double[] expected = all.get((j * WIDTH + i) * 4 + s);
                        double[] actual = part.get(k++);
                        assertEquals(pattern + " u of pixel (" + i + ", " + j + ")", expected[0], actual[0], 0);
                        assertEquals(pattern + " v of pixel (" + i + ", " + j + ")", expected[1], actual[1], 0);
                    }
                }
            }
        }
    }

    @Test
    public void aWindowRendersAnImageOfItsOwnSize() {
        RenderResult result = new Renderer(RenderPlan.of(scene(), 1).withWindow(new PixelWindow(8, 5, 1, 1)), 2).render();
        assertEquals(1, result.image.width());
        assertEquals(1, result.image.height());
        assertEquals(1, result.rays.camera);
        assertEquals("the default is the whole image", PixelWindow.whole(WIDTH, HEIGHT), RenderPlan.of(scene()).window());
    }

    @Test
    public void aWindowOutsideTheImageIsRefused() {
        try {
            RenderPlan.of(scene()).withWindow(new PixelWindow(6, 0, 4, 2));
            fail("a window past the right edge was accepted");
        } catch (IllegalArgumentException e) {
            assertEquals("the window 6,0,4,2 does not fit in the 9x6 image", e.getMessage());
        }
        assertTrue(new PixelWindow(5, 4, 4, 2).fitsIn(WIDTH, HEIGHT));
        assertFalse(new PixelWindow(5, 5, 4, 2).fitsIn(WIDTH, HEIGHT));
    }

    @Test
    public void parsesFourIntegersAndNamesWhatIsWrong() {
        assertEquals(new PixelWindow(1, 2, 30, 40), PixelWindow.parse(" 1, 2,30 ,40"));
        for (String bad : new String[] {"1,2,3", "1,2,3,x", "1,2,3,4,5", ""}) {
            try {
                PixelWindow.parse(bad);
                fail("parsed " + bad);
            } catch (IllegalArgumentException e) {
                assertEquals("a window is X,Y,WIDTH,HEIGHT (four integers, Y from the top), got '" + bad + "'", e.getMessage());
            }
        }
        try {
            PixelWindow.parse("0,0,0,5");
            fail("a window of no width was accepted");
        } catch (IllegalArgumentException e) {
            assertEquals("a window needs x, y ≥ 0 and a positive width and height, got 0,0,0,5", e.getMessage());
        }
    }
}
