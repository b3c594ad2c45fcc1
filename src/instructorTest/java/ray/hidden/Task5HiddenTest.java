package ray.hidden;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.image.Image;
import ray.math.Vec3;
import ray.shading.ClampTexture;
import ray.shading.RepeatTexture;
import ray.shading.Texture;
import ray.shading.TextureLookupsAccess;
import ray.testing.Points;
import ray.testing.StudentTask;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden lookup cases, seeded: images of every shape from 1×1 to 9×7 (one row, one column, wide,
 * tall), coordinates from −3 to 3 kept 0.2 of a texel from any edge between texels, and the lookup
 * as the shaders call it, through a hit's texture coordinates.
 */
@Points(value = 1, task = StudentTask.TEXTURE, visibility = Visibility.HIDDEN)
public class Task5HiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(StudentTask.TEXTURE);

    private static final int CASES = 400;

    /** A coordinate in [−3, 3] whose x·n + ½ is at least 0.2 from an integer. */
    private static double awayFromEdges(Random random, int n) {
        while (true) {
            double x = 6 * random.nextDouble() - 3;
            double scaled = x * n + 0.5;
            double fromEdge = Math.abs(scaled - Math.rint(scaled));
            if (fromEdge > 0.2) {
                return x;
            }
        }
    }

    private static void randomLookups(long seed, boolean repeat) {
        Random random = new Random(seed);
        for (int k = 0; k < CASES; k++) {
            int width = 1 + random.nextInt(9);
            int height = 1 + random.nextInt(7);
            Image image = TextureLookupsAccess.distinctTexels(width, height);
            Texture texture = repeat ? new RepeatTexture(image) : new ClampTexture(image);
            double u = awayFromEdges(random, width);
            double v = awayFromEdges(random, height);
            if (repeat) {
                TextureLookupsAccess.assertRepeat(texture, width, height, u, v);
            } else {
                TextureLookupsAccess.assertClamp(texture, width, height, u, v);
            }
        }
    }

    @Test
    @Points(value = 2, task = StudentTask.TEXTURE, visibility = Visibility.HIDDEN)
    public void repeatOnImagesOfEveryShape() {
        randomLookups(5_000_001, true);
    }

    @Test
    @Points(value = 2, task = StudentTask.TEXTURE, visibility = Visibility.HIDDEN)
    public void clampOnImagesOfEveryShape() {
        randomLookups(5_000_002, false);
    }

    @Test
    public void aOneTexelImageIsOneColorEverywhere() {
        Image one = new Image(1, 1);
        Vec3 color = new Vec3(0.2, 0.4, 0.6);
        one.set(0, 0, color);
        for (double u : new double[] {-2.3, -0.4, 0, 0.3, 0.9, 1.7, 12.2}) {
            assertEquals("RepeatTexture on a 1×1 image at u = v = " + u, color, new RepeatTexture(one).getTexColor(u, u));
            assertEquals("ClampTexture on a 1×1 image at u = v = " + u, color, new ClampTexture(one).getTexColor(u, u));
        }
    }

    @Test
    public void shadersLookUpTheHitsTextureCoordinates() {
        // Texture.colorAt(hit) passes the hit's (u, v), rounded to float as the course does, to getTexColor.
        Image image = TextureLookupsAccess.distinctTexels(8, 4);
        IntersectionRecord hit = new IntersectionRecord();
        hit.texU = 0.625; // column 5's center
        hit.texV = 0.25; // row 1's center
        Vec3 expected = TextureLookupsAccess.texel(8, 4, 5, 1);
        assertEquals("RepeatTexture.colorAt a hit with (u, v) = (0.625, 0.25) on an 8×4 image: texel (5, 1)", expected,
                new RepeatTexture(image).colorAt(hit));
        assertEquals("ClampTexture.colorAt the same hit", expected, new ClampTexture(image).colorAt(hit));
        hit.texU = 1.625;
        hit.texV = 3.25;
        assertEquals("RepeatTexture.colorAt (1.625, 3.25): texel (5, 1) again", expected, new RepeatTexture(image).colorAt(hit));
        assertTrue("ClampTexture.colorAt (1.625, 3.25): the top-right texel (7, 3)",
                TextureLookupsAccess.texel(8, 4, 7, 3).equals(new ClampTexture(image).colorAt(hit)));
    }
}
