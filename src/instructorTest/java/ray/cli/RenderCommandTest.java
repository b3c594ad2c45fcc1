package ray.cli;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Pattern;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.image.PngReader;

/** {@code ray1 render} on good scenes: the PNGs it writes, the summary and plan lines and the --stats JSON. */
public class RenderCommandTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private Path root;
    private Path output;

    @Before
    public void setUp() {
        root = folder.getRoot().toPath();
        output = root.resolve("out");
    }

    /** The summary line of a 4×4 scene: name, size, seconds, total rays and rays by kind. */
    private static Pattern summary(String name, long camera, long shadow) {
        return Pattern.compile(Pattern.quote(name) + " +4x4 +\\d+[.,]\\d\\d s +" + (camera + shadow)
                + " rays \\(camera " + camera + ", shadow " + shadow + ", reflection 0\\)");
    }

    /** The plan line of the floor scene (one white Lambertian triangle, one light), at 1 sample. */
    private static final String FLOOR_PLAN = "effects: lighting(1 shader) shadows(1 light);"
            + " skipped: specular, textures, reflection, antialiasing, transforms, vertex normals, bvh";

    @Test
    public void accelNoneRendersTheSameImageAndABadValueIsRefused() throws Exception {
        Path scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
        Path linear = root.resolve("linear");
        CliRun none = CliRun.of("render", "--accel", "none", "-o", linear.toString(), scene.toString());
        CliRun bvh = CliRun.of("render", "-o", output.toString(), scene.toString());
        assertEquals(none.toString(), 0, none.status);
        assertEquals(bvh.toString(), 0, bvh.status);
        assertArrayEquals(Files.readAllBytes(output.resolve("floor.png")), Files.readAllBytes(linear.resolve("floor.png")));
        CliRun bad = CliRun.of("render", "--accel", "kd-tree", "-o", output.toString(), scene.toString());
        assertEquals(bad.toString(), 2, bad.status);
        assertTrue(bad.err, bad.err.startsWith("--accel must be bvh (or framework), student or none, got 'kd-tree'\n"));
    }

    /** The students' tree (the solution's here) renders a mesh scene to the same bytes as the framework's, and says so in --stats. */
    @Test
    public void accelStudentSearchesMeshesWithTheStudentsTree() throws Exception {
        Path scene = Path.of("scenes", "mesh-smooth.xml").toAbsolutePath();
        Path framework = root.resolve("framework");
        Path students = root.resolve("students");
        Path stats = root.resolve("stats.json");
        CliRun bvh = CliRun.of("render", "--accel", "framework", "-o", framework.toString(), scene.toString());
        CliRun student = CliRun.of("render", "--accel", "student", "--stats", stats.toString(), "-o", students.toString(), scene.toString());
        assertEquals(bvh.toString(), 0, bvh.status);
        assertEquals(student.toString(), 0, student.status);
        assertArrayEquals(Files.readAllBytes(framework.resolve("mesh-smooth.png")), Files.readAllBytes(students.resolve("mesh-smooth.png")));
        String json = Files.readString(stats);
        assertTrue(json, json.contains("\"acceleration\": \"student\""));
    }

    /** Where the assignment has students write the tree, their render searches with it unless told otherwise. */
    @Test
    public void theStudentsTreeIsTheDefaultWhereTheyWriteIt() throws Exception {
        Path scene = Path.of("scenes", "two-boxes.xml").toAbsolutePath();
        ray.assignment.Assignment before = ray.assignment.Assignment.current();
        try {
            for (String preset : new String[] {"course-2019-part2", "course-2017"}) {
                ray.assignment.Assignment.use(ray.assignment.Assignment.preset(preset));
                Path stats = root.resolve(preset + ".json");
                CliRun run = CliRun.of("render", "--stats", stats.toString(), "-o", root.resolve(preset).toString(), scene.toString());
                assertEquals(run.toString(), 0, run.status);
                String mode = preset.equals("course-2017") ? "bvh" : "student";
                String json = Files.readString(stats);
                assertTrue(preset + ": " + json, json.contains("\"acceleration\": \"" + mode + "\""));
            }
        } finally {
            ray.assignment.Assignment.use(before);
        }
    }

    @Test
    public void cameraRaysPaintWhereEachRayCrossesTheImagePlane() throws Exception {
        Path scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
        CliRun run = CliRun.of("render", "--camera-rays", "-o", output.toString(), scene.toString());
        assertEquals(run.toString(), 0, run.status);
        Path picture = output.resolve("camera-rays/floor.png");
        assertEquals(run.toString(), "floor: camera rays, 4x4 -> " + picture + "\n", run.out);
        assertFalse("the camera-ray picture went to the render's place", Files.exists(output.resolve("floor.png")));
        BufferedImage png = PngReader.read(picture);
        // Pixel (i, j) is seen at ((i + ½)/4, (j + ½)/4): red and green 0.125, 0.375, 0.625, 0.875, which
        // the PNG stores as floor(255·x^(1/2.2) + ½) = 99, 163, 206, 240. PNG row 0 is the top (j = 3).
        int[] level = {99, 163, 206, 240};
        for (int i = 0; i < 4; i++) {
            for (int j = 0; j < 4; j++) {
                assertEquals("pixel " + i + ", " + j, (level[i] << 16) | (level[j] << 8), png.getRGB(i, 3 - j) & 0xffffff);
            }
        }
    }

    /** A student checking Task 1 keeps the renders that show the other tasks' work: the pictures go to a folder of their own. */
    @Test
    public void cameraRaysNeverReplaceTheRenders() throws Exception {
        Path scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
        CliRun render = CliRun.of("render", "-o", output.toString(), scene.toString());
        assertEquals(render.toString(), 0, render.status);
        byte[] rendered = Files.readAllBytes(output.resolve("floor.png"));
        CliRun rays = CliRun.of("render", "--camera-rays", "-o", output.toString(), scene.toString());
        assertEquals(rays.toString(), 0, rays.status);
        assertArrayEquals("--camera-rays changed the render", rendered, Files.readAllBytes(output.resolve("floor.png")));
        assertFalse("the camera-ray picture is the render",
                Arrays.equals(rendered, Files.readAllBytes(output.resolve("camera-rays/floor.png"))));
        // And the other way round: a render leaves the camera-ray pictures alone.
        byte[] picture = Files.readAllBytes(output.resolve("camera-rays/floor.png"));
        assertEquals(0, CliRun.of("render", "-o", output.toString(), scene.toString()).status);
        assertArrayEquals(picture, Files.readAllBytes(output.resolve("camera-rays/floor.png")));
    }

    @Test
    public void renderingOneSceneWritesItsPngAndOneSummaryLine() throws Exception {
        Path scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
        CliRun run = CliRun.of("render", "-o", output.toString(), scene.toString());

        assertEquals(run.toString(), 0, run.status);
        assertEquals(run.toString(), "", run.err);
        String[] lines = CliRun.lines(run.out);
        assertEquals(run.toString(), 2, lines.length);
        assertTrue(lines[0], summary("floor", 16, 16).matcher(lines[0].strip()).matches());
        assertEquals("  " + FLOOR_PLAN, lines[1]);

        BufferedImage png = PngReader.read(output.resolve("floor.png"));
        assertEquals(4, png.getWidth());
        assertEquals(4, png.getHeight());
        // The pixel right under the light, (0, 1), is PNG row 2: white Lambertian, I/r² = 4/4 = 1.
        assertEquals(0xffffff, png.getRGB(0, 2) & 0xffffff);
        // Pixel (3, 3): r² = 9 + 4 + 4 = 17, L = 8/17^1.5 = 0.11413, floor(255·0.11413^(1/2.2) + ½) = 95.
        assertEquals(0x5f5f5f, png.getRGB(3, 0) & 0xffffff);
        run.assertNoStackTrace();
    }

    /**
     * An 8×4 orthographic view at 45° down onto two white 2×2×2 boxes, left one given with minPt.y = 1
     * above maxPt.y = −1. The view maps pixel column i to x = i − 3.5, and the rows from the top to
     * t = 1.5, 0.5, −0.5, −1.5 along v = (0, 1, −1)/√2: a ray at t meets a box's front (z = 1) at
     * y = 1 + √2·t for −√2 ≤ t ≤ 0, and its top (y = 1) at z = 1 − √2·t for 0 ≤ t ≤ √2.
     */
    private static final String TWO_BOXES_ONE_UPSIDE_DOWN = """
            <scene>
              <camera type="OrthographicCamera">
                <viewPoint>0 5 5</viewPoint>
                <viewDir>0 -1 -1</viewDir>
                <viewWidth>8</viewWidth>
                <viewHeight>4</viewHeight>
              </camera>
              <image>8 4</image>
              <backColor>0.2 0.3 0.5</backColor>
              <light><position>0 6 6</position><intensity>60 60 60</intensity></light>
              <surface type="Box">
                <minPt>-3 1 -1</minPt>
                <maxPt>-1 -1 1</maxPt>
              </surface>
              <surface type="Box">
                <minPt>1 -1 -1</minPt>
                <maxPt>3 1 1</maxPt>
              </surface>
            </scene>
            """;

    @Test
    public void aBoxGivenUpsideDownWarnsOnceAndRendersAsTheCoursesRendererDoes() throws Exception {
        Path scene = CliRun.write(root.resolve("boxes.xml"), TWO_BOXES_ONE_UPSIDE_DOWN);
        CliRun run = CliRun.of("render", "-o", output.toString(), scene.toString());
        assertEquals(run.toString(), 0, run.status);
        assertEquals(run.toString(), scene + ":11:23: warning: Box minPt.y > maxPt.y; built from the corners as given,"
                + " as the course's renderer does\n", run.err);
        assertEquals(run.toString(), 2, CliRun.lines(run.out).length);
        BufferedImage png = PngReader.read(output.resolve("boxes.png"));
        // Row 1 (t = 0.5) sees the tops at z = 1 − √2/2 = 0.29289, row 2 (t = −0.5) the fronts at
        // y = 0.29289; columns 1 and 6 are x = −2.5 and 2.5. From the light at (0, 6, 6) each of these
        // four points is (∓2.5, 5.70711, 5) or (∓2.5, 5, 5.70711) away: r² = 63.8211, and the lit
        // face's n·l = 5/√63.8211 = 0.625876, so L = 60·0.625876/63.8211 = 0.588403, stored as
        // floor(255·0.588403^(1/2.2) + ½) = 200.
        int lit = 0xc8c8c8;
        assertEquals("the ordinary box's top", lit, png.getRGB(6, 1) & 0xffffff);
        assertEquals("the ordinary box's front", lit, png.getRGB(6, 2) & 0xffffff);
        // The upside-down box's top is its −y face (at minPt.y = 1): its normal (0, −1, 0) points away
        // from the light, so it is black. Its front, the +z face, still points out and is lit.
        assertEquals("the upside-down box's top", 0x000000, png.getRGB(1, 1) & 0xffffff);
        assertEquals("the upside-down box's front", lit, png.getRGB(1, 2) & 0xffffff);
        // Row 3 (t = −1.5) is below both boxes: the background, floor(255·(0.2, 0.3, 0.5)^(1/2.2) + ½).
        assertEquals(0x7b94ba, png.getRGB(1, 3) & 0xffffff);
        run.assertNoStackTrace();
    }

    @Test
    public void folderArgumentRendersEveryXmlFileRecursively() throws Exception {
        CliRun.write(root.resolve("scenes/a.xml"), CliRun.floorScene(""));
        CliRun.write(root.resolve("scenes/deeper/still/b.xml"), CliRun.floorScene(""));
        CliRun.write(root.resolve("scenes/notes.txt"), "not a scene");
        CliRun.write(root.resolve("scenes/deeper/c.xml.bak"), "not a scene either");
        CliRun run = CliRun.of("render", "-o", output.toString(), root.resolve("scenes").toString());

        assertEquals(run.toString(), 0, run.status);
        String[] lines = CliRun.lines(run.out);
        assertEquals(run.toString(), 4, lines.length);
        assertTrue(lines[0], summary("a", 16, 16).matcher(lines[0].strip()).matches());
        assertEquals("  " + FLOOR_PLAN, lines[1]);
        assertTrue(lines[2], summary("b", 16, 16).matcher(lines[2].strip()).matches());
        assertEquals("  " + FLOOR_PLAN, lines[3]);
        assertTrue(Files.isRegularFile(output.resolve("a.png")));
        assertTrue(Files.isRegularFile(output.resolve("b.png")));
        try (var files = Files.list(output)) {
            assertEquals("nothing else is written", 2, files.count());
        }
    }

    @Test
    public void samplesOptionOverridesTheScene() throws Exception {
        Path scene = CliRun.write(root.resolve("nine.xml"), CliRun.floorScene("  <samples>9</samples>\n"));

        CliRun asWritten = CliRun.of("render", "-o", output.toString(), scene.toString());
        assertEquals(asWritten.toString(), 0, asWritten.status);
        // 3×3 grid: 9·16 = 144 camera rays, each with one shadow ray
        String[] written = CliRun.lines(asWritten.out);
        assertTrue(asWritten.out, summary("nine", 144, 144).matcher(written[0].strip()).matches());
        assertTrue(written[1], written[1].contains(" antialiasing(3x3);"));

        CliRun overridden = CliRun.of("render", "--samples", "4", "-o", output.toString(), scene.toString());
        assertEquals(overridden.toString(), 0, overridden.status);
        String[] over = CliRun.lines(overridden.out);
        assertTrue(overridden.out, summary("nine", 64, 64).matcher(over[0].strip()).matches());
        assertTrue("the plan follows --samples: " + over[1], over[1].contains(" antialiasing(2x2);"));
    }

    @Test
    public void statsFileHoldsOneJsonObjectPerScene() throws Exception {
        CliRun.write(root.resolve("scenes/first.xml"), CliRun.floorScene(""));
        CliRun.write(root.resolve("scenes/second.xml"), CliRun.floorScene("  <samples>4</samples>\n"));
        Path stats = root.resolve("reports/stats.json");
        CliRun run = CliRun.of("render", "--threads", "3", "--stats", stats.toString(),
                "-o", output.toString(), root.resolve("scenes").toString());
        assertEquals(run.toString(), 0, run.status);

        JsonArray array = JsonParser.parseString(Files.readString(stats)).getAsJsonArray();
        assertEquals(2, array.size());
        String[] names = {"first", "second"};
        int[] samples = {1, 4};
        for (int k = 0; k < 2; k++) {
            JsonObject s = array.get(k).getAsJsonObject();
            assertEquals(names[k], s.get("scene").getAsString());
            assertEquals(4, s.get("width").getAsInt());
            assertEquals(4, s.get("height").getAsInt());
            assertEquals(samples[k], s.get("samples").getAsInt());
            assertEquals("--threads is honoured", 3, s.get("threads").getAsInt());
            double seconds = s.get("seconds").getAsDouble();
            assertTrue("seconds " + seconds, seconds >= 0 && seconds < 60);
            JsonObject rays = s.get("rays").getAsJsonObject();
            assertEquals(16 * samples[k], rays.get("camera").getAsLong());
            assertEquals(16 * samples[k], rays.get("shadow").getAsLong());
            assertEquals(0, rays.get("reflection").getAsLong());
            List<String> effects = new ArrayList<>();
            s.get("effects").getAsJsonArray().forEach(e -> effects.add(e.getAsString()));
            List<String> skipped = new ArrayList<>();
            s.get("skipped").getAsJsonArray().forEach(e -> skipped.add(e.getAsString()));
            assertEquals(samples[k] == 1 ? List.of("lighting(1 shader)", "shadows(1 light)")
                    : List.of("lighting(1 shader)", "shadows(1 light)", "antialiasing(2x2)"), effects);
            assertTrue(skipped.containsAll(List.of("specular", "reflection", "transforms", "vertex normals")));
            // One triangle: every camera and shadow ray is one intersection test, and no box is tested.
            assertEquals(32 * samples[k], s.get("intersectionTests").getAsLong());
            JsonObject byRay = s.get("intersectionTestsByRay").getAsJsonObject();
            assertEquals(16 * samples[k], byRay.get("camera").getAsLong());
            assertEquals(16 * samples[k], byRay.get("shadow").getAsLong());
            assertEquals(0, byRay.get("reflection").getAsLong());
            assertEquals(0, s.get("boxTests").getAsLong());
            assertEquals("bvh", s.get("acceleration").getAsString());
            assertEquals("Lambertian only", 0, s.get("specularEvaluations").getAsLong());
            assertEquals("no texture", 0, s.get("textureLookups").getAsLong());
        }
        try (var files = Files.list(stats.getParent())) {
            assertEquals("no temporary file is left beside the stats", 1, files.count());
        }
    }

    @Test
    public void threadsOptionShowsInTheStats() throws Exception {
        Path scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
        Path stats = root.resolve("stats.json");
        CliRun run = CliRun.of("render", "--threads", "1", "--stats", stats.toString(), "-o", output.toString(), scene.toString());
        assertEquals(run.toString(), 0, run.status);
        JsonObject s = JsonParser.parseString(Files.readString(stats)).getAsJsonArray().get(0).getAsJsonObject();
        assertEquals(1, s.get("threads").getAsInt());
    }

    @Test
    public void jitterOptionShowsInThePlanAndTheStats() throws Exception {
        Path scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
        Path stats = root.resolve("stats.json");
        CliRun run = CliRun.of("render", "--samples", "4", "--jitter", "--seed", "7", "--stats", stats.toString(),
                "-o", output.toString(), scene.toString());
        assertEquals(run.toString(), 0, run.status);
        assertTrue(run.out, run.out.contains("effects: lighting(1 shader) shadows(1 light) antialiasing(2x2 jittered);"));
        JsonObject s = JsonParser.parseString(Files.readString(stats)).getAsJsonArray().get(0).getAsJsonObject();
        assertEquals("jittered (seed 7)", s.get("sampling").getAsString());

        CliRun grid = CliRun.of("render", "--samples", "4", "--stats", stats.toString(), "-o", output.toString(), scene.toString());
        assertEquals(grid.toString(), 0, grid.status);
        s = JsonParser.parseString(Files.readString(stats)).getAsJsonArray().get(0).getAsJsonObject();
        assertEquals("grid", s.get("sampling").getAsString());
        assertTrue(grid.out, grid.out.contains("antialiasing(2x2);"));
    }
}
