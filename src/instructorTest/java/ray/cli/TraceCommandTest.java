package ray.cli;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.IntersectionRecord;
import ray.Ray;
import ray.camera.OrthographicCamera;
import ray.image.PngReader;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.scene.SceneFiles;
import ray.shading.RGBNormals;
import ray.surface.Group;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.inspect.PixelTrace;

/**
 * {@code ray1 trace}: the numbers it prints for pixels whose every step follows by hand from the
 * scene file, Y counted from the top, the blocker of a shadow named, the 8-bit value equal to the
 * rendered PNG's pixel, a group loop that disagrees with its surfaces flagged, and one-line errors.
 */
public class TraceCommandTest {
    private static final Pattern NUMBER = Pattern.compile("-?\\d+(?:\\.\\d+)?(?:e[-+]?\\d+)?");
    /** The trace prints six significant digits. */
    private static final double TOL = 1e-5;

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    /**
     * one-sphere.xml at 301×301 (odd, so the middle pixel's center is on the view axis): the ray
     * (0,0,5) + t(0,0,−2) hits the unit sphere at t = 2, at (0,0,1) with n = (0,0,1). Key light 40
     * at (3,4,5): l = (3,4,4)/√41, r² = 41, n·l = 4/√41, adds kd·40·(4/√41)/41. Fill 6 at (−3,−1,6):
     * l = (−3,−1,5)/√35, r² = 35, n·l = 5/√35, adds kd·6·(5/√35)/35. kd = (0.2, 0.3, 0.8).
     */
    @Test
    public void middlePixelOfOneSphereHitsThePoleAndSumsTwoLambertLights() throws Exception {
        Path scene = variant("one-sphere.xml", "<image>300 300</image>", "<image>301 301</image>");
        CliRun run = CliRun.of("trace", scene.toString(), "150", "150");
        assertEquals(run.toString(), 0, run.status);
        String out = run.out;
        assertVec(v(150, 150, 0), vec2(row(out, "(i, j)")), 0);
        assertVec(v(0, 0, 5), vec(row(out, "origin")), 0);
        assertVec(v(0, 0, -2), vec(row(out, "direction")), 0);
        String sphere = row(out, "#1 Sphere");
        assertTrue(sphere, sphere.contains("hit  t = 2  at (0, 0, 1)") && sphere.contains("← nearest"));
        assertVec(v(0, 0, 1), vec(row(out, "normal")), 0);
        assertTrue(out, out.contains("✓ the nearest hit"));

        Vec3 kd = v(0.2, 0.3, 0.8);
        String key = section(out, "Light 1", "Light 2");
        assertVec(v(3, 4, 4).times(1 / Math.sqrt(41)), vec(row(key, "l ")), TOL);
        assertEquals(41, numbers(row(key, "r "))[1], TOL);
        assertEquals(4 / Math.sqrt(41), numbers(row(key, "n·l"))[0], TOL);
        assertTrue(key, row(key, "shadow  ").contains("not blocked"));
        assertVec(kd.times(40 * 4 / Math.sqrt(41) / 41), lastVec(row(key, "adds")), TOL);
        String fill = section(out, "Light 2", "    L ");
        assertEquals(35, numbers(row(fill, "r "))[1], TOL);
        assertEquals(5 / Math.sqrt(35), numbers(row(fill, "n·l"))[0], TOL);
        assertVec(kd.times(6 * 5 / Math.sqrt(35) / 35), lastVec(row(fill, "adds")), TOL);

        Vec3 radiance = kd.times(40 * 4 / (41 * Math.sqrt(41)) + 6 * 5 / (35 * Math.sqrt(35)));
        assertVec(radiance, vec(row(out, "radiance")), TOL);
        // L = (0.150868, 0.226303, 0.603474); x^(1/2.2)·255 = 107.93, 129.78, 202.71, rounded.
        assertArrayEquals(new int[] {108, 130, 203}, rgb8(out));
    }

    /**
     * one-sphere-phong.xml at 301×301, middle pixel: n = e = (0,0,1), l = (3,4,4)/√41, so
     * h = normalize(l + e) bisects them: n·h = cos(θ/2) = √((1 + cos θ)/2) with cos θ = 4/√41, and
     * the specular term is ks·40·(n·h)^60/41 with ks = (0.8, 0.8, 0.8).
     */
    @Test
    public void phongPixelShowsTheHalfVectorAndTheSpecularTerm() throws Exception {
        Path scene = variant("one-sphere-phong.xml", "<image>300 300</image>", "<image>301 301</image>");
        String out = CliRun.of("trace", scene.toString(), "150", "150").out;
        double cosTheta = 4 / Math.sqrt(41);
        Vec3 h = v(3, 4, 4).times(1 / Math.sqrt(41)).plus(v(0, 0, 1)).normalized();
        assertVec(h, vec(row(out, "h ")), TOL);
        assertEquals(Math.sqrt((1 + cosTheta) / 2), numbers(row(out, "n·h"))[0], TOL);
        double specular = 0.8 * 40 * Math.pow((1 + cosTheta) / 2, 30) / 41;
        assertVec(v(specular, specular, specular), lastVec(row(out, "specular").replaceAll("\\s+\\(not gated.*", "")), TOL);
    }

    /** one-sphere-phong.xml, top-left corner: the ray passes the sphere and shows <backColor>0.1 0.11 0.14</backColor>. */
    @Test
    public void pixelThatMissesEverythingShowsTheBackColor() {
        String out = CliRun.of("trace", "scenes/one-sphere-phong.xml", "0", "0").out;
        assertTrue(out, row(out, "#1 Sphere").endsWith("miss"));
        assertTrue(out, out.contains("none: the pixel shows the background color (0.1, 0.11, 0.14)"));
        assertVec(v(0.1, 0.11, 0.14), vec(row(out, "radiance")), 0);
        int[] expected = {gamma8(0.1), gamma8(0.11), gamma8(0.14)};
        assertEquals("0.1^(1/2.2)·255 = 89.53", 90, expected[0]);
        assertArrayEquals(expected, rgb8(out));
    }

    /**
     * two-boxes.xml, pixel (212, 115): the ground in the red box's shadow from the key light. The
     * shadow ray meets the box's −z face, z = −1.2, first; the fill light is not blocked.
     */
    @Test
    public void shadowedPixelNamesTheBlockingBoxAndItsT() {
        CliRun run = CliRun.of("trace", "scenes/two-boxes.xml", "212", "115");
        String out = run.out;
        assertTrue(out, row(out, "surface").startsWith("surface      #1 Box (-5, -0.5, -5) to (5, 0, 5) › triangle #8 (+y face)"));
        String key = section(out, "Light 1", "Light 2");
        String blocked = row(key, "shadow  ");
        assertTrue(blocked, blocked.contains("BLOCKED by #2 Box (-1.6, 0, -1.2) to (-0.4, 2.4, 0) › triangle #10 (−z face)"));
        double[] ray = numbers(row(key, "shadow ray"));
        double t = numbers(blocked.substring(blocked.indexOf("at t = ")))[0];
        // The blocker's t puts it on the shadow ray, in the plane z = −1.2.
        Vec3 origin = v(ray[0], ray[1], ray[2]);
        Vec3 direction = v(ray[3], ray[4], ray[5]);
        assertEquals(-1.2, origin.z + t * direction.z, 1e-5);
        assertVec(origin.plusScaled(t, direction), lastVec(blocked), 1e-5);
        assertTrue(key, row(key, "adds").contains("nothing: the shadow ray is blocked"));
        assertTrue(out, row(section(out, "Light 2", "    L "), "shadow  ").contains("not blocked"));
    }

    /**
     * An orthographic 4×4 view of [−2, 2]² whose only sphere (radius 0.3, RGBNormals) sits at
     * (−0.5, 1.5): only pixel column i = 1 of the top row j = 3 sees it. An image viewer shows that
     * row first, so it is y = 0: the trace and the PNG agree that y counts from the top.
     */
    @Test
    public void yCountsFromTheTopOfThePngAndJFromTheBottom() throws Exception {
        Path scene = folder.getRoot().toPath().resolve("corner.xml");
        CliRun.write(scene, "<scene>\n"
                + "  <camera type=\"OrthographicCamera\"><viewPoint>0 0 5</viewPoint>"
                + "<viewWidth>4</viewWidth><viewHeight>4</viewHeight></camera>\n"
                + "  <image>4 4</image>\n"
                + "  <surface type=\"Sphere\"><shader type=\"RGBNormals\"/><center>-0.5 1.5 0</center><radius>0.3</radius></surface>\n"
                + "</scene>\n");
        String top = CliRun.of("trace", scene.toString(), "1", "0").out;
        assertVec(v(1, 3, 0), vec2(row(top, "(i, j)")), 0);
        assertVec(v(-0.5, 1.5, 5), vec(row(top, "origin")), 0);
        assertTrue(top, row(top, "#1 Sphere").contains("hit  t = 4.7  at (-0.5, 1.5, 0.3)"));
        // n = (0, 0, 1), so (n + 1)/2 = (0.5, 0.5, 1): 0.5^(1/2.2)·255 = 186.08 → 186.
        assertArrayEquals(new int[] {186, 186, 255}, rgb8(top));
        String bottom = CliRun.of("trace", scene.toString(), "1", "3").out;
        assertVec(v(1, 0, 0), vec2(row(bottom, "(i, j)")), 0);
        assertTrue(bottom, row(bottom, "#1 Sphere").endsWith("miss"));

        Path png = render(scene, new String[0]).resolve("corner.png");
        BufferedImage image = PngReader.read(png);
        assertArrayEquals(new int[] {186, 186, 255}, pixel(image, 1, 0));
        assertArrayEquals(new int[] {0, 0, 0}, pixel(image, 1, 3));
    }

    /** For pixels picked at random (fixed seed) in several scenes, the trace's 8-bit value is the rendered PNG's pixel. */
    @Test
    public void eightBitValueEqualsTheRenderedPngPixel() throws Exception {
        Random random = new Random(20240611);
        String[][] cases = {
            {"scenes/one-sphere.xml"}, {"scenes/one-sphere-phong.xml"}, {"scenes/two-boxes.xml"},
            {"scenes/glazed-sphere.xml"}, {"scenes/group-transforms.xml"}, {"scenes/rgb-normals.xml"},
            {"scenes/antialiased.xml", "--samples", "4"}, {"scenes/textured/globe.xml"}, {"scenes/textured/tablecloth.xml"},
            {"scenes/textured/diagnostic.xml"}, {"scenes/cylinder.xml"},
        };
        for (String[] c : cases) {
            Path sceneFile = Path.of(c[0]);
            String[] options = java.util.Arrays.copyOfRange(c, 1, c.length);
            BufferedImage image = PngReader.read(render(sceneFile, options).resolve(SceneFiles.nameOf(sceneFile) + ".png"));
            int[][] pixels = {
                {image.getWidth() / 2, image.getHeight() / 2},
                {random.nextInt(image.getWidth()), random.nextInt(image.getHeight())},
                {random.nextInt(image.getWidth()), random.nextInt(image.getHeight())},
                {random.nextInt(image.getWidth()), random.nextInt(image.getHeight())},
            };
            for (int[] p : pixels) {
                List<String> args = new ArrayList<>(List.of("trace"));
                args.addAll(List.of(options));
                args.addAll(List.of(c[0], String.valueOf(p[0]), String.valueOf(p[1])));
                CliRun run = CliRun.of(args.toArray(new String[0]));
                assertEquals(run.toString(), 0, run.status);
                assertArrayEquals(c[0] + " pixel " + p[0] + ", " + p[1], pixel(image, p[0], p[1]), rgb8(run.out));
                assertTrue(run.out, !run.out.contains("the trace computed"));
            }
        }
    }

    /**
     * globe.xml, pixel (160, 120) hits the unit sphere at the origin: (u, v) follow from the hit's
     * unit normal by u = ½ + atan2(x, z)/2π, v = ½ + asin(y)/π; the texel is column (int) (u·512 + ½)
     * and row (int) ((1 − v)·256 + ½) of the texture file, counted from its top, and its color / 255
     * is the kd that the diffuse terms use.
     */
    @Test
    public void texturedPixelShowsItsTexCoordsTexelAndColor() throws Exception {
        CliRun run = CliRun.of("trace", "scenes/textured/globe.xml", "160", "120");
        assertEquals(run.toString(), 0, run.status);
        String out = run.out;
        Vec3 n = vec(row(out, "normal"));
        double u = 0.5 + Math.atan2(n.x, n.z) / (2 * Math.PI);
        double v = 0.5 + Math.asin(n.y) / Math.PI;
        String lookup = section(out, "Shading at the hit", "Light 1");
        assertVec(v(u, v, 0), vec2(row(lookup, "(u, v)")), TOL);
        int i = (int) (u * 512 + 0.5);
        int fromTop = (int) ((1 - (float) v) * 256 + 0.5);
        assertEquals(256, i);
        assertEquals(106, fromTop);
        String texel = row(lookup, "texel");
        assertTrue(texel, texel.startsWith("texel        (256, 106) of 512×256") && texel.contains("rows count from the image file's top"));
        int[] file = pixel(PngReader.read(Path.of("scenes/textures/globe.png")), i, fromTop);
        double[] color = numbers(row(out, "its color"));
        assertArrayEquals(file, new int[] {(int) color[0], (int) color[1], (int) color[2]});
        Vec3 kd = v(file[0] / 255.0, file[1] / 255.0, file[2] / 255.0);
        assertVec(kd, lastVec(row(out, "its color")), TOL);
        assertVec(kd, vec(row(out, "kd ")), TOL);
        assertTrue(out, row(out, "diffuse").contains("= " + row(out, "kd ").substring(2).strip().split("   ")[0]));
        assertTrue(out, !out.contains("!"));
    }

    /** group-transforms.xml, pixel (250, 130) hits the vase: the mesh is scaled by 1.2 and moved by (2, 0, −0.5). */
    @Test
    public void transformedGroupIsTestedWithTheRayInItsOwnCoordinates() {
        String out = CliRun.of("trace", "scenes/group-transforms.xml", "250", "130").out;
        assertTrue(out, out.contains("#5 Mesh scenes/meshes/vase.obj (598 triangles), transformed:"));
        String local = out.substring(out.indexOf("#5 Mesh"));
        double[] ray = numbers(row(local, "children tested"));
        double[] world = numbers(row(out, "origin"));
        double[] worldDirection = numbers(row(out, "direction"));
        // The local ray is M⁻¹ applied to the camera ray: origin (p − (2, 0, −0.5))/1.2, direction d/1.2.
        assertVec(v(world[0] - 2, world[1], world[2] + 0.5).times(1 / 1.2), v(ray[0], ray[1], ray[2]), TOL);
        assertVec(v(worldDirection[0], worldDirection[1], worldDirection[2]).times(1 / 1.2), v(ray[3], ray[4], ray[5]), TOL);
        assertTrue(out, row(out, "surface").contains("#5 Mesh scenes/meshes/vase.obj (598 triangles) › triangle #"));
        assertTrue(out, out.contains("✓ the nearest hit"));
    }

    /**
     * glazed-sphere.xml, pixel (160, 100): the glaze over the sphere's top. R = R0 + (1 − R0)(1 − n·e)^5
     * with R0 = 0.04, the mirror direction 2(n·e)n − e, and L = R·L_mirror + (1 − R)·L_substrate.
     */
    @Test
    public void glazedPixelShowsSchlickTheMirrorRayAndTheBlend() {
        String out = CliRun.of("trace", "scenes/glazed-sphere.xml", "160", "100").out;
        double[] ne = numbers(row(out, "n, e"));
        Vec3 n = v(ne[0], ne[1], ne[2]);
        Vec3 e = v(ne[3], ne[4], ne[5]);
        double cos = numbers(row(out, "n·e"))[0];
        assertEquals(n.dot(e), cos, TOL);
        assertEquals(0.04 + 0.96 * Math.pow(1 - cos, 5), numbers(row(out, "R "))[0], TOL);
        assertVec(n.times(2 * cos).minus(e), lastVec(row(out, "mirror")), TOL);
        assertTrue(out, row(out, "it hits").contains("nothing: it sees the background (0.45, 0.6, 0.85)"));
        String line = row(out, "L            R · L_mirror");
        double[] blend = numbers(line.substring(line.indexOf("= ")));
        // R · (Lm) + (1 − R) · (Ls) = (L), the numbers in the order printed.
        for (int k = 0; k < 3; k++) {
            assertEquals(blend[0] * blend[1 + k] + blend[4] * blend[5 + k], blend[8 + k], 1e-5);
        }
    }

    @Test
    public void coordinatesOutsideTheImageAreAOneLineErrorWithNonZeroStatus() {
        for (String[] xy : new String[][] {{"300", "0"}, {"0", "300"}, {"-1", "5"}}) {
            CliRun run = CliRun.of("trace", "scenes/one-sphere.xml", xy[0], xy[1]);
            assertNotEquals(run.toString(), 0, run.status);
            String[] errors = CliRun.lines(run.err);
            assertEquals(run.toString(), 1, errors.length);
            assertTrue(run.toString(), errors[0].startsWith("error: pixel (" + xy[0] + ", " + xy[1] + ") is outside the 300×300 image"));
            assertTrue(run.toString(), errors[0].contains("y from 0 to 299 (from the top)"));
            assertEquals(run.toString(), "", run.out);
            run.assertNoStackTrace();
        }
    }

    @Test
    public void aSceneWarningGoesToStderrOnceAndTheTraceStillRuns() throws Exception {
        Path scene = CliRun.write(folder.getRoot().toPath().resolve("floor.xml"), CliRun.floorScene(CliRun.UPSIDE_DOWN_BOX));
        CliRun run = CliRun.of("trace", scene.toString(), "0", "2");
        assertEquals(run.toString(), 0, run.status);
        assertEquals(run.toString(), CliRun.upsideDownBoxWarning(scene) + "\n", run.err);
        // Pixel (0, 2) from the top is right under the light (RenderCommandTest's floor): white.
        assertTrue(run.out, run.out.matches("(?s).*8-bit RGB\\s+\\(255, 255, 255\\).*"));
        run.assertNoStackTrace();
    }

    @Test
    public void missingSceneFileIsAOneLineErrorWithNonZeroStatus() {
        CliRun run = CliRun.of("trace", "scenes/no-such-scene.xml", "1", "1");
        assertNotEquals(run.toString(), 0, run.status);
        assertEquals(run.toString(), "error: scenes/no-such-scene.xml:1:1: no such file; expected the path of a scene file",
                run.err.strip());
        run.assertNoStackTrace();
    }

    /** A group that keeps the last hit instead of the closest: the closest-hit section names the closer surface. */
    @Test
    public void groupThatKeepsTheLastHitIsFlaggedAgainstTheSmallestT() {
        Group lastHit = new Group() {
            @Override
            public boolean intersect(IntersectionRecord out, Ray ray) {
                boolean any = false;
                for (Surface s : children()) {
                    any |= s.intersect(out, ray.copy());
                }
                return any;
            }
        };
        lastHit.addSurface(new Sphere(v(0, 0, 0), 1));
        lastHit.addSurface(new Sphere(v(0, 0, -4), 1));
        String out = traceOneRayScene(lastHit);
        // Seen from z = 5: the near sphere at t = 4, the far one at t = 8.
        assertTrue(out, row(out, "t ").endsWith(" 8"));
        assertTrue(out, out.contains("! the smallest t in the list above is 4, at #1 Group (2 surfaces) › #1 Sphere center (0, 0, 0)"));
    }

    /** A group that finds nothing (the handout's stub) while its surfaces are hit: the trace points at Task 4. */
    @Test
    public void groupThatFindsNothingIsFlaggedAsTheStub() {
        Group none = new Group() {
            @Override
            public boolean intersect(IntersectionRecord out, Ray ray) {
                return false;
            }
        };
        none.addSurface(new Sphere(v(0, 0, 0), 1));
        String out = traceOneRayScene(none);
        assertTrue(out, out.contains("none: the pixel shows the background color"));
        assertTrue(out, out.contains("#1 Group (1 surface) › #1 Sphere center (0, 0, 0), radius 1 is hit at t = 4 when tested alone:"
                + " is Group.intersect still the stub? See TODO(Task 4)"));
    }

    /**
     * A plane z = 0, a surface type the framework has never heard of: it describes itself, and
     * the trace names it so, with no edit in the inspection code.
     */
    private static final class ZPlane extends Surface {
        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            double t = -ray.origin.z / ray.direction.z;
            if (!(ray.start < t && t < ray.end)) {
                return false;
            }
            out.t = t;
            out.location = ray.pointAt(t);
            out.normal = v(0, 0, 1);
            out.surface = this;
            return true;
        }

        @Override
        public String describe(java.util.function.DoubleFunction<String> number) {
            return "ZPlane at height " + number.apply(0);
        }
    }

    @Test
    public void aNewSurfaceTypeIsNamedAsItDescribesItself() {
        String out = traceOneRayScene(new ZPlane());
        assertTrue(out, out.contains("#1 ZPlane at height 0  hit  t = 5  at (0, 0, 0)  ← nearest"));
        assertTrue(out, out.contains("surface      #1 ZPlane at height 0"));
    }

    /** A 1×1 orthographic view from z = 5 straight down −z, onto {@code surface}, traced with the API. */
    private static String traceOneRayScene(Surface surface) {
        OrthographicCamera camera = new OrthographicCamera();
        camera.setViewPoint(v(0, 0, 5));
        camera.complete();
        Scene scene = new Scene();
        scene.setCamera(camera);
        scene.setImage(1, 1);
        surface.setShader(new RGBNormals());
        scene.addSurface(surface.complete());
        scene.complete();
        StringWriter text = new StringWriter();
        try (PrintWriter out = new PrintWriter(text)) {
            assertNotNull(new PixelTrace(scene, "test scene", false, 0).run(0, 0, out));
        }
        return text.toString();
    }

    // --- reading the trace's text ---

    /** The first line that starts with {@code label} after its indentation ("l " is the row l, not "Light"). */
    private static String row(String text, String label) {
        for (String line : text.split("\n")) {
            if (line.strip().startsWith(label)) {
                return line.strip();
            }
        }
        throw new AssertionError("no line starting with \"" + label + "\" in:\n" + text);
    }

    /** The text from the line holding {@code from} up to the line holding {@code to}. */
    private static String section(String text, String from, String to) {
        int start = text.indexOf(from);
        assertTrue("no \"" + from + "\" in:\n" + text, start >= 0);
        int end = text.indexOf(to, start + from.length());
        return end < 0 ? text.substring(start) : text.substring(start, end);
    }

    private static double[] numbers(String line) {
        Matcher m = NUMBER.matcher(line.replaceFirst("^[^0-9(-]*", ""));
        List<Double> values = new ArrayList<>();
        while (m.find()) {
            values.add(Double.parseDouble(m.group()));
        }
        return values.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /** The first three numbers of a line. */
    private static Vec3 vec(String line) {
        double[] n = numbers(line);
        return v(n[0], n[1], n[2]);
    }

    /** The first two numbers of a line, as (a, b, 0). */
    private static Vec3 vec2(String line) {
        double[] n = numbers(line);
        return v(n[0], n[1], 0);
    }

    /** The last parenthesized triple of a line. */
    private static Vec3 lastVec(String line) {
        return vec(line.substring(line.lastIndexOf('(')));
    }

    private static int[] rgb8(String out) {
        String line = row(out, "8-bit RGB");
        double[] n = numbers(line.substring(line.indexOf('(')));
        return new int[] {(int) n[0], (int) n[1], (int) n[2]};
    }

    /** floor(255·x^(1/2.2) + ½) for x in (0, 1). */
    private static int gamma8(double x) {
        return (int) Math.floor(255 * Math.pow(x, 1 / 2.2) + 0.5);
    }

    private static int[] pixel(BufferedImage image, int x, int y) {
        int rgb = image.getRGB(x, y);
        return new int[] {(rgb >> 16) & 255, (rgb >> 8) & 255, rgb & 255};
    }

    /** Renders the scene with {@code ray1 render} into a fresh folder, which it returns. */
    private Path render(Path scene, String[] options) throws Exception {
        Path out = Files.createTempDirectory(folder.getRoot().toPath(), "png");
        List<String> args = new ArrayList<>(List.of("render", "-o", out.toString()));
        args.addAll(List.of(options));
        args.add(scene.toString());
        CliRun run = CliRun.of(args.toArray(new String[0]));
        assertEquals(run.toString(), 0, run.status);
        return out;
    }

    /** A copy of a shipped scene (one without meshes) with one piece of text replaced. */
    private Path variant(String name, String from, String to) throws Exception {
        String text = Files.readString(Path.of("scenes", name));
        assertTrue(name + " has " + from, text.contains(from));
        return CliRun.write(folder.getRoot().toPath().resolve(name), text.replace(from, to));
    }
}
