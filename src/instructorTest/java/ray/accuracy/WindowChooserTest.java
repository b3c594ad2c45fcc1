package ray.accuracy;

import static org.junit.Assert.assertEquals;

import org.junit.Test;
import ray.image.Image;
import ray.math.Vec3;
import ray.render.PixelWindow;

/** The study's window goes where the image has the most edge, which is where sampling shows. */
public class WindowChooserTest {
    /** A black w×h image with a white square of side s whose top-left pixel is (x, y), y from the top. */
    private static Image square(int w, int h, int x, int y, int s) {
        Image image = new Image(w, h);
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                int row = h - 1 - j;
                boolean inside = i >= x && i < x + s && row >= y && row < y + s;
                image.set(i, j, inside ? new Vec3(1, 1, 1) : Vec3.ZERO);
            }
        }
        return image;
    }

    @Test
    public void theWindowCoversTheOnlyEdges() {
        // A 6-pixel square at (40, 20): its edges lie in columns 39..45 and rows 19..25 (file rows).
        PixelWindow w = WindowChooser.busiest(square(64, 48, 40, 20, 6), 1, 16);
        assertEquals(16, w.width);
        assertEquals(16, w.height);
        for (int[] corner : new int[][] {{39, 19}, {45, 25}}) {
            String where = "window " + w + " holds (" + corner[0] + ", " + corner[1] + ")";
            assertEquals(where, true, corner[0] >= w.x && corner[0] < w.x + w.width && corner[1] >= w.y && corner[1] < w.y + w.height);
        }
    }

    @Test
    public void aFlatImageGivesTheTopLeftWindow() {
        assertEquals(new PixelWindow(0, 0, 8, 8), WindowChooser.busiest(square(30, 20, 0, 0, 0), 1, 8));
    }

    @Test
    public void theLastPositionIsTriedEvenOffTheStride() {
        // 30 wide, window 8: starts 0, 4, ..., 20 and then 22, the last that fits, where the edge is.
        PixelWindow w = WindowChooser.busiest(square(30, 8, 29, 0, 1), 1, 8);
        assertEquals(22, w.x);
    }

    @Test
    public void aWindowLargerThanTheImageIsTheWholeImage() {
        assertEquals(PixelWindow.whole(10, 6), WindowChooser.busiest(square(10, 6, 2, 2, 2), 1, 64));
    }
}
