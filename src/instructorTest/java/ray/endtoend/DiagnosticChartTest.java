package ray.endtoend;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Path;
import java.util.Locale;
import org.junit.BeforeClass;
import org.junit.Test;
import ray.image.Image;
import ray.math.Vec3;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneLoader;

/**
 * The diagnostic chart (scenes/textured/diagnostic.xml) rendered at full size, every pixel of its two
 * textured squares against the shading worked out here from the scene file alone: the pixel's ray,
 * its hit on the square, the square's (u, v), the course's texel (column (int)(u·4 + ½), row
 * (int)((1 − v)·4 + ½) from the top, wrapped or clamped) of the 4×4 ruler, and the Lambertian or
 * Phong sum under the one light. Pixels whose (u, v) lie within a tenth of a texel of an edge between
 * texels are left out, since a rounding there may go either way.
 */
public class DiagnosticChartTest {
    private static final int WIDTH = 320;
    private static final int HEIGHT = 240;
    private static final Vec3 EYE = new Vec3(0, 0.5, 6);
    private static final Vec3 LIGHT = new Vec3(-3, 4, 7);
    private static final Vec3 INTENSITY = new Vec3(75, 75, 72);
    private static final int TEXELS = 4;
    private static Image render;

    /** A textured square: centered at (x, −0.1, 0), 0.9 wide, facing +z; u and v start at its left and bottom edges. */
    private enum Square {
        REPEAT_C(0.6, 0, -0.5, false), CLAMP_D(1.8, -0.25, -0.25, true);

        final double centerX;
        final double u0;
        final double v0;
        final boolean phongAndClamp;

        Square(double centerX, double u0, double v0, boolean phongAndClamp) {
            this.centerX = centerX;
            this.u0 = u0;
            this.v0 = v0;
            this.phongAndClamp = phongAndClamp;
        }
    }

    @BeforeClass
    public static void renderTheChart() {
        Scene scene = SceneLoader.load(Path.of("scenes/textured/diagnostic.xml"));
        assertEquals(WIDTH, scene.getWidth());
        render = new Renderer(scene, 0, 0).render().image;
    }

    /** Texel (column, row from the top) of textures/ruler.png, as TextureGenerator.ruler draws it, / 255. */
    static Vec3 ruler(int column, int row) {
        int[] rgb;
        if (row == 0) {
            rgb = new int[] {230, 20, 20};
        } else if (row == TEXELS - 1) {
            rgb = new int[] {20, 40, 230};
        } else if (column == 0) {
            rgb = new int[] {250, 230, 30};
        } else if (column == TEXELS - 1) {
            rgb = new int[] {255, 255, 255};
        } else {
            rgb = (column + row) % 2 == 0 ? new int[] {30, 110, 40} : new int[] {150, 220, 120};
        }
        return new Vec3(rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
    }

    /** The course's row for v, from the top, before wrapping or clamping. */
    private static int courseRow(double v) {
        return (int) ((1 - v) * TEXELS + 0.5);
    }

    /** The rule that is one row off: rounded from the bottom, then flipped. */
    private static int rowFlippedAfterRounding(double v) {
        return TEXELS - 1 - Math.floorMod((int) (v * TEXELS + 0.5), TEXELS);
    }

    private static int fit(int index, boolean clamp) {
        return clamp ? Math.max(0, Math.min(TEXELS - 1, index)) : Math.floorMod(index, TEXELS);
    }

    private static boolean nearATexelEdge(double coordinate) {
        double scaled = coordinate * TEXELS + 0.5;
        return Math.abs(scaled - Math.rint(scaled)) < 0.1;
    }

    /**
     * Radiance at point p of a square facing +z with diffuse color kd: Lambertian kd·I·(n·l)/r², plus
     * for D the Blinn–Phong term ks·I·(n·h)^40/r² with ks = 0.5.
     */
    private static Vec3 shade(Vec3 p, Vec3 kd, boolean phong) {
        Vec3 toLight = LIGHT.minus(p);
        double r2 = toLight.dot(toLight);
        Vec3 l = toLight.normalized();
        Vec3 diffuse = new Vec3(kd.x * INTENSITY.x, kd.y * INTENSITY.y, kd.z * INTENSITY.z).times(Math.max(0, l.z) / r2);
        if (!phong) {
            return diffuse;
        }
        Vec3 h = l.plus(EYE.minus(p).normalized()).normalized();
        return diffuse.plus(INTENSITY.times(0.5 * Math.pow(Math.max(0, h.z), 40) / r2));
    }

    private static void checkSquare(Square square) {
        int checked = 0;
        int offByOneDiffers = 0;
        for (int i = 0; i < WIDTH; i++) {
            for (int j = 0; j < HEIGHT; j++) {
                // Pixel (i, j), j from the bottom: the ray eye + t·(s, t, −1.5) meets z = 0 at t = 4.
                double s = ((i + 0.5) / WIDTH - 0.5) * 1.2;
                double t = ((j + 0.5) / HEIGHT - 0.5) * 0.9;
                Vec3 p = new Vec3(4 * s, 0.5 + 4 * t, 0);
                double across = (p.x - square.centerX) / 0.9 + 0.5; // 0 at the left edge, 1 at the right
                double up = (p.y + 0.1) / 0.9 + 0.5;
                if (across <= 0.01 || across >= 0.99 || up <= 0.01 || up >= 0.99) {
                    continue; // off the square, or at its rim where the sphere's shadow or the background may show
                }
                double u = square.u0 + 1.5 * across;
                double v = square.v0 + 1.5 * up;
                if (nearATexelEdge(u) || nearATexelEdge(1 - v)) {
                    continue;
                }
                int column = fit((int) (u * TEXELS + 0.5), square.phongAndClamp);
                int row = fit(courseRow(v), square.phongAndClamp);
                Vec3 expected = shade(p, ruler(column, row), square.phongAndClamp);
                Vec3 got = render.get(i, j);
                if (got.minus(expected).length() > 1e-9 * expected.length()) {
                    throw new AssertionError(String.format(Locale.ROOT,
                            "%s pixel (%d, %d from the bottom) sees (u, v) = (%.4f, %.4f): texel (%d, %d) of the ruler, radiance %s;"
                                    + " the render has %s",
                            square, i, j, u, v, column, row, expected, got));
                }
                checked++;
                int offRow = square.phongAndClamp ? Math.max(0, Math.min(TEXELS - 1, TEXELS - 1 - (int) (v * TEXELS + 0.5)))
                        : rowFlippedAfterRounding(v);
                offByOneDiffers += ruler(column, offRow).equals(ruler(column, row)) ? 0 : 1;
            }
        }
        // The square is 60 × 60 pixels; the edges between texels take a fifth of each side.
        assertTrue(square + ": only " + checked + " pixels checked", checked > 2000);
        assertTrue(square + ": a lookup one row off would change only " + offByOneDiffers + " of " + checked + " pixels",
                offByOneDiffers > checked / 3);
    }

    @Test
    public void theRepeatSquareShowsTheCoursesTexelAtEveryPixel() {
        checkSquare(Square.REPEAT_C);
    }

    @Test
    public void theClampSquareShowsTheCoursesTexelAtEveryPixel() {
        checkSquare(Square.CLAMP_D);
    }

    /**
     * Two pixels of square C worked out in full, both at column 210: s = (210.5/320 − ½)·1.2 =
     * 0.189375, so p.x = 0.7575, 0.675 of the way across, u = 1.0125, column (int)(4.55) = 4, which
     * wraps to 0.
     * <ul>
     * <li>Row 86: t = (86.5/240 − ½)·0.9 = −0.125625, p.y = −0.0025, 0.6083 up, v = 0.4125, row
     *     (int)(0.5875·4 + ½) = (int) 2.85 = 2: yellow, the left column.</li>
     * <li>Row 76: t = −0.163125, p.y = −0.1525, 0.4417 up, v = 0.1625, row (int) 3.85 = 3: blue, the
     *     bottom row. Rows flipped after rounding take 3 − (int)(0.65 + ½) = row 2 there, yellow.</li>
     * </ul>
     */
    @Test
    public void twoPixelsWorkedOutByHand() {
        assertEquals(ruler(0, 2), new Vec3(250 / 255.0, 230 / 255.0, 30 / 255.0));
        Vec3 yellow = shade(new Vec3(0.7575, -0.0025, 0), ruler(0, 2), false);
        assertTrue(render.get(210, 86) + " vs " + yellow, render.get(210, 86).minus(yellow).length() < 1e-9);
        Vec3 blue = shade(new Vec3(0.7575, -0.1525, 0), ruler(0, 3), false);
        assertTrue(render.get(210, 76) + " vs " + blue, render.get(210, 76).minus(blue).length() < 1e-9);
    }
}
