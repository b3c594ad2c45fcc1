package ray.render;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.image.PngReader;
import ray.image.PngWriter;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.shading.RGBNormals;
import ray.surface.Sphere;

/** Exact pixel values of tiny scenes, worked out by hand, in the Image and in the PNG. */
public class TinySceneTest {
    private static final double TOL = 1e-12;

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    /**
     * 4×4 orthographic view of x, y in [−2, 2] looking down at a Lambertian floor z = 0 with
     * kd = (1, 0.5, 0.25), lit by I = (4, 4, 4) at (−1.5, −0.5, 2). Pixel (i, j) sees the point
     * (i − 1.5, j − 1.5, 0), so the vector to the light is (−i, 1 − j, 2): r² = i² + (j − 1)² + 4,
     * n·l = 2/r and L = kd·4·(2/r)/r² = kd·8/r³.
     */
    private static Scene litFloor() {
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 5), 4, 4), 4, 4);
        scene.addLight(new Light(v(-1.5, -0.5, 2), v(4, 4, 4)));
        scene.addSurface(TestScenes.plane(0, true, new Lambertian(v(1, 0.5, 0.25))));
        scene.complete();
        return scene;
    }

    @Test
    public void litFloorMatchesLambertByHandInEveryPixel() {
        RenderResult result = new Renderer(litFloor(), 1, 2).render();
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                double r = Math.sqrt(i * i + (j - 1) * (j - 1) + 4);
                double red = 8 / (r * r * r);
                assertVec("pixel (" + i + ", " + j + ")", v(red, red / 2, red / 4), result.image.get(i, j), TOL);
            }
        }
        // Spelled out: straight under the light r = 2, L = kd; one pixel right r² = 5, 8/5^1.5 = 0.715541752...
        assertVec(v(1, 0.5, 0.25), result.image.get(0, 1), TOL);
        assertVec(v(0.7155417527999326, 0.3577708763999663, 0.17888543819998315), result.image.get(1, 1), TOL);
        assertVec("r² = 17", v(0.11413441178180374, 0.05706720589090187, 0.028533602945450934), result.image.get(3, 3), TOL);
        assertEquals(16, result.rays.camera);
        assertEquals(16, result.rays.shadow);
    }

    @Test
    public void litFloorPngHasTheExpectedBytesTopRowFirst() throws Exception {
        Scene scene = litFloor();
        RenderResult result = new Renderer(scene, 1, 1).render();
        Path file = folder.getRoot().toPath().resolve("floor.png");
        PngWriter.write(result.image, scene.getExposure(), file);
        BufferedImage png = PngReader.read(file);

        // Red bytes, floor(255·(8/r³)^(1/2.2) + ½); PNG row 0 is j = 3.
        // r² by pixel:   j=3: 8 9 12 17   j=2: 5 6 9 14   j=1: 4 5 8 13   j=0: 5 6 9 14
        int[][] redByRow = {
            {159, 147, 121, 95},
            {219, 193, 147, 109},
            {255, 219, 159, 114},
            {219, 193, 147, 109},
        };
        for (int row = 0; row < 4; row++) {
            for (int i = 0; i < 4; i++) {
                assertEquals("red of PNG (" + i + ", " + row + ")", redByRow[row][i], (png.getRGB(i, row) >> 16) & 0xff);
            }
        }
        // All three channels of two pixels: (1, 0.5, 0.25) → (255, 186, 136); r² = 17 → (95, 69, 51).
        assertArrayEquals(new int[] {255, 186, 136}, rgb(png, 0, 2));
        assertArrayEquals(new int[] {95, 69, 51}, rgb(png, 3, 0));
    }

    @Test
    public void missedPixelsGetBackColorAndHitsShowTheSphere() {
        // 4×4 view of [−2, 2]²: pixel centers at ±0.5, ±1.5. A sphere of radius 0.8 at the origin
        // covers the four central centers (distance √0.5 ≈ 0.707) and none of the others (≥ √2.5).
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 5), 4, 4), 4, 4);
        Vec3 back = v(0.25, 0.5, 0.125);
        scene.setBackColor(back);
        Sphere sphere = new Sphere(Vec3.ZERO, 0.8);
        sphere.setShader(new RGBNormals());
        scene.addSurface(sphere.complete());
        scene.complete();
        RenderResult result = new Renderer(scene, 1, 3).render();
        // At (±0.5, ±0.5): z = √(0.64 − 0.5) = √0.14, n = (±0.5, ±0.5, √0.14)/0.8 = (±0.625, ±0.625, 0.4677...).
        double blue = (Math.sqrt(0.14) / 0.8 + 1) / 2;
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                boolean central = (i == 1 || i == 2) && (j == 1 || j == 2);
                Vec3 expected = !central ? back
                        : v(i == 1 ? 0.1875 : 0.8125, j == 1 ? 0.1875 : 0.8125, blue);
                assertVec("pixel (" + i + ", " + j + ")", expected, result.image.get(i, j), 1e-12);
            }
        }
        assertEquals(0.7338535866, blue, 1e-10);
    }

    @Test
    public void emptySceneIsBackColorEverywhereWithAnySampleCount() {
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 5), 1, 1), 3, 2);
        scene.setBackColor(v(0.25, 0.5, 0.125));
        scene.complete();
        RenderResult result = new Renderer(scene, 4, 1).render();
        for (int j = 0; j < 2; j++) {
            for (int i = 0; i < 3; i++) {
                // Binary fractions: the average of four equal samples is exact.
                assertVec(v(0.25, 0.5, 0.125), result.image.get(i, j), 0);
            }
        }
    }

    private static int[] rgb(BufferedImage png, int x, int y) {
        int p = png.getRGB(x, y);
        return new int[] {(p >> 16) & 0xff, (p >> 8) & 0xff, p & 0xff};
    }
}
