package ray.render;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.image.Image;
import ray.scene.Scene;
import ray.scene.SceneLoader;
import ray.shading.Lambertian;
import ray.surface.Sphere;
import ray.surface.SurfaceKind;
import ray.testing.StudentTask;

/**
 * {@link Renderer#renderWithKinds()}: what each pixel's camera rays hit first, counted by hand on
 * {@link SphereAndTriangle}, through groups, transforms, boxes and cylinders, over several samples,
 * in a window; and the image is the same, bit for bit, as a render that records nothing.
 */
public class PixelKindsTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private static final SurfaceKind S = SurfaceKind.SPHERE;
    private static final SurfaceKind T = SurfaceKind.TRIANGLE;
    private static final SurfaceKind B = SurfaceKind.BACKGROUND;

    @Test
    public void eachPixelNamesWhatItsCameraRayHitFirstCountedFromTheTop() {
        PixelKinds kinds = new Renderer(SphereAndTriangle.scene(), 1, 2).renderWithKinds().kinds;
        assertEquals(SphereAndTriangle.WIDTH, kinds.width());
        assertEquals(SphereAndTriangle.HEIGHT, kinds.height());
        // (x, y) sees (x − 9.5, 4.5 − y).
        assertEquals("(−9.5, 4.5): nothing", B, kinds.at(0, 0));
        assertEquals("(−5.5, 0.5): the sphere", S, kinds.at(4, 4));
        assertEquals("(−2.5, −0.5) is √6.5 from the sphere's center", S, kinds.at(7, 5));
        assertEquals("(−1.5, 0.5) is √12.5 > 3.5 from it", B, kinds.at(8, 4));
        assertEquals("(0.5, 0.5): between them", B, kinds.at(10, 4));
        assertEquals("(1.5, 0.5): the triangle's corner column", T, kinds.at(11, 4));
        assertEquals("(1.5, 3.5): a + b = 7, just inside the long edge", T, kinds.at(11, 1));
        assertEquals("(1.5, 4.5): above the triangle", B, kinds.at(11, 0));
        assertEquals("(8.5, −3.5): a + b = 7 at the far corner", T, kinds.at(18, 8));
        assertEquals("(8.5, −2.5): a + b = 8, outside", B, kinds.at(18, 7));
        assertEquals("(1.5, −4.5): below the triangle", B, kinds.at(11, 9));
        // The bottom row is under the triangle's lower edge y = −4; row 8 is its first.
        assertEquals(SphereAndTriangle.TRIANGLE_PIXELS, kinds.count(T));
        assertEquals(SphereAndTriangle.SPHERE_PIXELS, kinds.count(S));
        assertEquals(200 - 36 - 32, kinds.count(B));
        assertEquals(0, kinds.count(SurfaceKind.CYLINDER) + kinds.count(SurfaceKind.OTHER));
    }

    /** Row 4 from the top, x = 0 … 19, drawn out: a render of only one sample per pixel. */
    @Test
    public void aRowReadsAsDrawn() {
        PixelKinds kinds = new Renderer(SphereAndTriangle.scene(), 1, 1).renderWithKinds().kinds;
        SurfaceKind[] row = new SurfaceKind[20];
        for (int x = 0; x < 20; x++) {
            row[x] = kinds.at(x, 4);
        }
        // y = 0.5: the sphere spans |x + 5| < √(12.25 − 0.25) ≈ 3.46, x = −7.5 … −2.5 → columns 2 … 7;
        // the triangle x from 1 to 9.25 − 4.5 = 4.75, x = 1.5 … 4.5 → columns 11 … 14.
        assertArrayEquals(new SurfaceKind[] {B, B, S, S, S, S, S, S, B, B, B, T, T, T, T, B, B, B, B, B}, row);
    }

    @Test
    public void recordingChangesNoBitOfTheImageAndAPlainRenderRecordsNothing() {
        for (int samples : new int[] {1, 4, 9}) {
            Scene scene = SphereAndTriangle.scene();
            RenderResult plain = new Renderer(scene, samples, 2).render();
            RenderResult recorded = new Renderer(scene, samples, 2).renderWithKinds();
            assertNull(plain.kinds);
            assertSameBits(samples + " samples", plain.image, recorded.image);
            assertEquals(plain.rays.camera, recorded.rays.camera);
            assertEquals(plain.rays.shadow, recorded.rays.shadow);
        }
    }

    /**
     * Several samples: the kind most of them hit, a surface on a tie. A sphere of radius 0.2 around a
     * pixel's center is hit by that pixel's center ray alone, 1 of 9 on a 3×3 grid (the others are
     * 1/3 away): the background. One of radius 0.3 a quarter pixel below another pixel's center is hit
     * by the two lower samples of a 2×2 grid (¼ away; the upper two are √0.3125 ≈ 0.56 away): a tie,
     * so the sphere.
     */
    @Test
    public void aPixelOfSeveralSamplesTakesTheKindMostHitASurfaceOnATie() {
        // Pixel (2, 1) of a 4×3 view of [−2, 2] × [−1.5, 1.5] sees (0.5, 0): y from the top.
        Scene center = tinySphere(v(0.5, 0, 0), 0.2);
        assertEquals(S, new Renderer(center, 1, 1).renderWithKinds().kinds.at(2, 1));
        assertEquals("1 of 9 samples hit it", B, new Renderer(center, 9, 1).renderWithKinds().kinds.at(2, 1));
        Scene low = tinySphere(v(0.5, -0.25, 0), 0.3);
        assertEquals("the center ray passes ¼ above the sphere's center, inside its 0.3", S,
                new Renderer(low, 1, 1).renderWithKinds().kinds.at(2, 1));
        PixelKinds four = new Renderer(low, 4, 1).renderWithKinds().kinds;
        assertEquals("2 of 4 samples hit it: a tie goes to the surface", S, four.at(2, 1));
        assertEquals(1, four.count(S));
    }

    private static Scene tinySphere(ray.math.Vec3 center, double radius) {
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 10), 4, 3), 4, 3);
        Sphere sphere = new Sphere(center, radius);
        sphere.setShader(new Lambertian(v(1, 1, 1)));
        scene.addSurface(sphere.complete());
        scene.complete();
        return scene;
    }

    /**
     * A hit's record names the primitive, never the group or transform around it: a box in a moved
     * group is triangles, a sphere scaled into an ellipsoid is a sphere (beyond its own radius),
     * a cylinder is a cylinder. 30×10 pixels, one unit each: (x, y) sees (x − 14.5, 4.5 − y).
     */
    @Test
    public void primitivesInsideGroupsAndTransformsAreNamedByTheirOwnKind() throws Exception {
        Path file = folder.getRoot().toPath().resolve("kinds.xml");
        Files.writeString(file, String.join("\n",
                "<scene>",
                "  <camera type=\"OrthographicCamera\"><viewPoint>0 0 10</viewPoint><viewDir>0 0 -1</viewDir>",
                "    <viewUp>0 1 0</viewUp><viewWidth>30</viewWidth><viewHeight>10</viewHeight></camera>",
                "  <image>30 10</image>",
                "  <shader name=\"grey\" type=\"Lambertian\"><diffuseColor>0.5 0.5 0.5</diffuseColor></shader>",
                "  <surface type=\"Group\"><translate>-10 0 0</translate>",
                "    <surface type=\"Group\">",
                "      <surface type=\"Box\"><shader ref=\"grey\"/><minPt>-2 -2 -1</minPt><maxPt>2 2 1</maxPt></surface>",
                "    </surface>",
                "  </surface>",
                "  <surface type=\"Group\"><scale>2 1 1</scale>",
                "    <surface type=\"Sphere\"><shader ref=\"grey\"/><center>0 0 0</center><radius>2</radius></surface>",
                "  </surface>",
                "  <surface type=\"Cylinder\"><shader ref=\"grey\"/><center>10 -2 0</center><radius>2</radius><height>4</height></surface>",
                "</scene>", ""), StandardCharsets.UTF_8);
        PixelKinds kinds = new Renderer(SceneLoader.load(file), 1, 2).renderWithKinds().kinds;
        assertEquals("(−14.5, 4.5)", B, kinds.at(0, 0));
        assertEquals("(−9.5, 0.5): the box, moved 10 left", T, kinds.at(5, 4));
        assertEquals("(−7.5, 0.5): right of the box", B, kinds.at(7, 4));
        assertEquals("(0.5, 0.5): the ellipsoid", S, kinds.at(15, 4));
        assertEquals("(3.5, 0.5): the ellipsoid, beyond the sphere's own radius 2", S, kinds.at(18, 4));
        assertEquals("(10.5, 0.5): the cylinder's side", SurfaceKind.CYLINDER, kinds.at(25, 4));
        assertEquals("(12.5, 0.5): right of the cylinder", B, kinds.at(27, 4));
        assertEquals("the box's 4×4 pixels", 16, kinds.count(T));
        assertEquals("the cylinder's 4×4 pixels", 16, kinds.count(SurfaceKind.CYLINDER));
        assertEquals(0, kinds.count(SurfaceKind.OTHER));
    }

    /** A window's kinds are the whole render's, at the window's place; the image is unchanged there too. */
    @Test
    public void aWindowRecordsItsOwnPixelsCountedFromItsTopLeft() {
        Scene scene = SphereAndTriangle.scene();
        PixelKinds whole = new Renderer(scene, 1, 2).renderWithKinds().kinds;
        RenderPlan windowPlan = RenderPlan.of(scene, 4).withWindow(new PixelWindow(9, 2, 6, 5));
        RenderResult part = new Renderer(windowPlan, 2).renderWithKinds();
        assertSameBits("window", new Renderer(windowPlan, 2).render().image, part.image);
        RenderPlan onePerPixel = RenderPlan.of(scene, 1).withWindow(new PixelWindow(9, 2, 6, 5));
        PixelKinds kinds = new Renderer(onePerPixel, 1).renderWithKinds().kinds;
        assertEquals(6, kinds.width());
        assertEquals(5, kinds.height());
        for (int y = 0; y < 5; y++) {
            for (int x = 0; x < 6; x++) {
                assertEquals("(" + x + ", " + y + ")", whole.at(9 + x, 2 + y), kinds.at(x, y));
            }
        }
    }

    /** Shipped scenes: the same bits either way, and the kinds their files describe. */
    @Test
    public void shippedScenesRenderTheSameBitsAndShowTheirKinds() {
        Scene transforms = SceneLoader.load(Path.of("scenes/group-transforms.xml"));
        RenderResult plain = new Renderer(transforms, 0, 2).render();
        RenderResult recorded = new Renderer(transforms, 0, 2).renderWithKinds();
        assertSameBits("group-transforms", plain.image, recorded.image);
        assertTrue("boxes and the vase are triangles", recorded.kinds.count(T) > 0);
        assertTrue("the squashed sphere", recorded.kinds.count(S) > 0);
        assertTrue("the sky", recorded.kinds.count(B) > 0);
        assertEquals(0, recorded.kinds.count(SurfaceKind.CYLINDER) + recorded.kinds.count(SurfaceKind.OTHER));

        Scene cylinders = SceneLoader.load(Path.of("scenes/cylinder.xml"));
        RenderResult withKinds = new Renderer(cylinders, 0, 2).renderWithKinds();
        assertSameBits("cylinder", new Renderer(cylinders, 0, 2).render().image, withKinds.image);
        assertTrue(withKinds.kinds.count(SurfaceKind.CYLINDER) > 0);
        assertEquals(0, withKinds.kinds.count(S) + withKinds.kinds.count(SurfaceKind.OTHER));

        // 16 samples per pixel, in a window of 40×30.
        Scene antialiased = SceneLoader.load(Path.of("scenes/antialiased.xml"));
        RenderPlan window = RenderPlan.of(antialiased).withWindow(new PixelWindow(100, 100, 40, 30));
        assertSameBits("antialiased", new Renderer(window, 2).render().image, new Renderer(window, 2).renderWithKinds().image);
    }

    @Test
    public void eachKindNamesItsTaskAsTheStudentsTestsNumberThem() {
        assertEquals(StudentTask.of("sphere").number, SurfaceKind.SPHERE.task());
        assertEquals(StudentTask.of("triangle").number, SurfaceKind.TRIANGLE.task());
        assertEquals(StudentTask.of("cylinder").number, SurfaceKind.CYLINDER.task());
        assertEquals("triangles (Task 3)", SurfaceKind.TRIANGLE.phrase(380));
        assertEquals("a sphere (Task 2)", SurfaceKind.SPHERE.phrase(1));
        assertEquals("cylinders (Task 6)", SurfaceKind.CYLINDER.phrase(2));
        assertEquals("the background", SurfaceKind.BACKGROUND.phrase(13));
        assertEquals("the background", SurfaceKind.BACKGROUND.phrase(1));
        assertEquals("other surfaces", SurfaceKind.OTHER.phrase(2));
        assertEquals(SurfaceKind.OTHER, SurfaceKind.of(null));
    }

    private static void assertSameBits(String what, Image expected, Image actual) {
        assertEquals(expected.width(), actual.width());
        assertEquals(expected.height(), actual.height());
        for (int j = 0; j < expected.height(); j++) {
            for (int i = 0; i < expected.width(); i++) {
                assertEquals(what + ": pixel (" + i + ", " + j + ") from the bottom", expected.get(i, j), actual.get(i, j));
            }
        }
    }
}
