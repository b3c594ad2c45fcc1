package ray.inspect;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.cli.Ray1Command;

/**
 * {@code ray1 explore}'s API through the JDK's HttpClient, against what the command line says: the
 * image is the PNG {@code ray1 render} writes, and every traced pixel's value, text and facts are
 * {@code ray1 trace}'s. Bad parameters get a 400 with one line; nothing outside the page and the
 * API is served, whatever the path says.
 */
public class ExploreApiTest {
    private static final HttpClient HTTP = HttpClient.newHttpClient();
    private static final Pattern EIGHT_BIT = Pattern.compile("8-bit RGB\\s+\\((\\d+), (\\d+), (\\d+)\\)");

    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    @Test(timeout = 300_000)
    public void pixelsAndTracesAreTheCommandLinesOnSeveralScenes() throws Exception {
        for (String scene : List.of("scenes/one-sphere.xml", "scenes/wire-box-ortho.xml", "scenes/group-transforms.xml",
                "scenes/textured/globe.xml", "scenes/mesh-smooth.xml")) {
            Path out = folder.newFolder().toPath();
            assertEquals(scene + " renders", 0, Ray1Command.run(new PrintWriter(new StringWriter()), new PrintWriter(new StringWriter()),
                    "render", "-o", out.toString(), scene));
            BufferedImage png = ImageIO.read(out.resolve(Path.of(scene).getFileName().toString().replace(".xml", ".png")).toFile());
            try (Explorer explorer = Explorer.start(Path.of(scene), null, 0)) {
                BufferedImage served = ImageIO.read(new ByteArrayInputStream(bytes(explorer, "api/image.png", 200)));
                assertEquals(scene, png.getWidth(), served.getWidth());
                for (int y = 0; y < png.getHeight(); y++) {
                    for (int x = 0; x < png.getWidth(); x++) {
                        assertEquals(scene + " pixel (" + x + ", " + y + ") of api/image.png", png.getRGB(x, y), served.getRGB(x, y));
                    }
                }
                JsonObject summary = json(explorer, "api/scene", 200);
                assertEquals(png.getWidth(), summary.get("width").getAsInt());
                assertNotNull(scene + " has its reference", summary.get("reference").getAsJsonObject());
                assertTrue(scene + " matches its reference", summary.getAsJsonObject("reference").get("passed").getAsBoolean());
                Random random = new Random(scene.hashCode());
                List<int[]> pixels = new ArrayList<>(List.of(new int[] {0, 0}, new int[] {png.getWidth() - 1, png.getHeight() - 1},
                        new int[] {png.getWidth() / 2, png.getHeight() / 2}));
                for (int k = 0; k < 4; k++) {
                    pixels.add(new int[] {random.nextInt(png.getWidth()), random.nextInt(png.getHeight())});
                }
                for (int[] p : pixels) {
                    String where = scene + " pixel (" + p[0] + ", " + p[1] + ")";
                    JsonObject story = json(explorer, "api/trace?x=" + p[0] + "&y=" + p[1], 200);
                    int rgb = png.getRGB(p[0], p[1]);
                    assertEquals(where + ": value is the PNG's", List.of(rgb >> 16 & 255, rgb >> 8 & 255, rgb & 255), ints(story.getAsJsonArray("value")));
                    String trace = cli("trace", scene, String.valueOf(p[0]), String.valueOf(p[1]));
                    assertEquals(where + ": the trace text is ray1 trace's", trace, story.get("trace").getAsString());
                    Matcher m = EIGHT_BIT.matcher(trace);
                    assertTrue(trace, m.find());
                    assertEquals(where + ": value is ray1 trace's", List.of(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)),
                            Integer.parseInt(m.group(3))), ints(story.getAsJsonArray("value")));
                    assertEquals(where + ": the reference's pixel", ints(story.getAsJsonArray("value")), ints(story.getAsJsonArray("reference")));
                    JsonElement closest = story.get("closest");
                    if (!closest.isJsonNull()) {
                        assertTrue(where + ": the closest hit's surface is in the trace", trace.contains("surface      "
                                + closest.getAsJsonObject().get("path").getAsString()));
                    } else {
                        assertTrue(where + ": no hit in the trace either", trace.contains("none: the pixel shows the background"));
                    }
                }
            }
        }
    }

    /** Pixel (150, 149) of one-sphere, by hand: its camera ray, the sphere's near root, the hit, the normal, both lights unblocked. */
    @Test(timeout = 120_000)
    public void oneSpheresCenterPixelIsTheHandComputedHit() throws Exception {
        try (Explorer explorer = Explorer.start(Path.of("scenes/one-sphere.xml"), null, 0)) {
            JsonObject story = json(explorer, "api/trace?x=150&y=149", 200);
            assertEquals(150, story.get("i").getAsInt());
            assertEquals(150, story.get("j").getAsInt());
            // imageU = imageV = 150.5/300; planeU = planeV = (imageU − ½)·1 = 1/600; direction planeU·u + planeV·v − 2·w with the default basis.
            double a = 1.0 / 600;
            JsonObject ray = story.getAsJsonObject("cameraRay");
            assertVec(new double[] {0, 0, 5}, ray.getAsJsonArray("origin"), 0);
            assertVec(new double[] {a, a, -2}, ray.getAsJsonArray("direction"), 1e-15);
            assertTrue("the segment's end is ∞ (null in JSON)", ray.get("end").isJsonNull());
            assertEquals("∞", ray.get("endText").getAsString());
            // |o + t·d|² = 1 with o = (0, 0, 5): (4 + 2a²)t² − 20t + 24 = 0, near root (20 − √(16 − 192a²)) / (8 + 4a²).
            double t = (20 - Math.sqrt(16 - 192 * a * a)) / (8 + 4 * a * a);
            double[] hit = {a * t, a * t, 5 - 2 * t};
            JsonArray hits = story.getAsJsonArray("hits");
            assertEquals(1, hits.size());
            JsonObject sphere = hits.get(0).getAsJsonObject();
            assertEquals("#1 Sphere center (0, 0, 0), radius 1", sphere.get("path").getAsString());
            assertEquals("sphere", sphere.get("kind").getAsString());
            assertTrue(sphere.get("hit").getAsBoolean());
            assertTrue(sphere.get("nearest").getAsBoolean());
            assertEquals(t, sphere.get("t").getAsDouble(), 1e-12);
            assertVec(hit, sphere.getAsJsonArray("location"), 1e-12);
            assertVec(hit, sphere.getAsJsonArray("normal"), 1e-12);
            JsonObject closest = story.getAsJsonObject("closest");
            assertEquals(t, closest.get("t").getAsDouble(), 1e-12);
            assertEquals("✓ the nearest hit in the list above", closest.get("check").getAsString());
            // The solution's hit claims nothing the contract rules out (RecordChecksTest covers the flags).
            assertEquals(0, closest.getAsJsonArray("recordChecks").size());
            JsonArray lights = story.getAsJsonArray("lights");
            assertEquals(2, lights.size());
            JsonObject key = lights.get(0).getAsJsonObject();
            assertVec(new double[] {3, 4, 5}, key.getAsJsonArray("position"), 0);
            assertFalse(key.get("blocked").getAsBoolean());
            assertTrue(key.get("blocker").isJsonNull());
            // n·l with l = normalize(light − hit), and the Lambertian term kd · I · max(0, n·l) / r².
            double[] toLight = {3 - hit[0], 4 - hit[1], 5 - hit[2]};
            double r2 = toLight[0] * toLight[0] + toLight[1] * toLight[1] + toLight[2] * toLight[2];
            double nl = (hit[0] * toLight[0] + hit[1] * toLight[1] + hit[2] * toLight[2]) / Math.sqrt(r2);
            assertEquals(nl, key.get("nDotL").getAsDouble(), 1e-12);
            assertVec(new double[] {0.2 * 40 * nl / r2, 0.3 * 40 * nl / r2, 0.8 * 40 * nl / r2}, key.getAsJsonArray("diffuse"), 1e-12);
            assertNotNull(key.getAsJsonObject("shadowRay"));
        }
    }

    /**
     * Under the course's 2019 conventions the page shows 2019's terms: the center of
     * scenes-2019/one-sphere-lambertian.xml meets the sphere head on at (0, 0, 1), its light 4 away
     * straight ahead, so the diffuse term is ρd/π · 64 · 1/16.
     */
    @Test(timeout = 120_000)
    public void under2019TheDiffuseTermIsRhoOverPi() throws Exception {
        ray.scene.SceneOptions y2019 = ray.scene.SceneOptions.of(ray.shading.Course.Y2019, null);
        try (Explorer explorer = Explorer.start(Path.of("scenes-2019/one-sphere-lambertian.xml"), null, 0, y2019)) {
            JsonObject story = json(explorer, "api/trace?x=100&y=100", 200);
            JsonObject light = story.getAsJsonArray("lights").get(0).getAsJsonObject();
            assertEquals(1, light.get("nDotL").getAsDouble(), 1e-12);
            double scale = 64.0 / 16 / Math.PI;
            assertVec(new double[] {0.8 * scale, 0.5 * scale, 0.2 * scale}, light.getAsJsonArray("diffuse"), 1e-12);
            assertTrue(light.get("agreesWithFormula").getAsBoolean());
        }
    }

    /** The page gets each light's formula share beside the shader's own, which agree for the framework's shaders. */
    @Test(timeout = 120_000)
    public void eachLightsFormulaShareAgreesWithTheShader() throws Exception {
        try (Explorer explorer = Explorer.start(Path.of("scenes/lights-and-shadows.xml"), null, 0)) {
            JsonObject story = json(explorer, "api/trace?x=160&y=150", 200);
            JsonObject key = story.getAsJsonArray("lights").get(0).getAsJsonObject();
            assertVec(new double[] {0.953844, 0.79487, 0.590475}, key.getAsJsonArray("formula"), 1e-6);
            for (JsonElement l : story.getAsJsonArray("lights")) {
                assertTrue(l.toString(), l.getAsJsonObject().get("agreesWithFormula").getAsBoolean());
            }
        }
    }

    /** A pixel in a shadow: the blocked light names the blocker that ray1 trace names. */
    @Test(timeout = 120_000)
    public void aBlockedLightNamesTheBlockerTheTraceNames() throws Exception {
        String scene = "scenes/two-boxes.xml";
        try (Explorer explorer = Explorer.start(Path.of(scene), null, 0)) {
            JsonObject summary = json(explorer, "api/scene", 200);
            int w = summary.get("width").getAsInt();
            int h = summary.get("height").getAsInt();
            for (int y = h - 1; y >= 0; y -= 7) {
                for (int x = 0; x < w; x += 7) {
                    JsonObject story = json(explorer, "api/trace?x=" + x + "&y=" + y, 200);
                    for (JsonElement l : story.getAsJsonArray("lights")) {
                        JsonObject light = l.getAsJsonObject();
                        if (light.get("blocked").getAsBoolean()) {
                            String trace = cli("trace", scene, String.valueOf(x), String.valueOf(y));
                            String blocker = light.getAsJsonObject("blocker").get("path").getAsString();
                            assertTrue(trace, trace.contains("BLOCKED by " + blocker + " at t = "));
                            assertEquals(0, light.getAsJsonArray("adds").get(0).getAsDouble(), 0);
                            return;
                        }
                    }
                }
            }
            throw new AssertionError(scene + " has no pixel in a shadow on a 7-pixel grid");
        }
    }

    @Test(timeout = 120_000)
    public void badParametersGetA400InOneLine() throws Exception {
        try (Explorer explorer = Explorer.start(Path.of("scenes/one-sphere.xml"), null, 0)) {
            for (String[] c : new String[][] {
                    {"api/trace", "missing x; expected /api/trace?x=X&y=Y"},
                    {"api/trace?x=3", "missing y; expected"},
                    {"api/trace?x=abc&y=1", "x must be a whole number, but was \"abc\"; expected"},
                    {"api/trace?x=1.5&y=1", "x must be a whole number, but was \"1.5\""},
                    {"api/trace?x=1&y=99999999999", "y must be a whole number, but was \"99999999999\""},
                    {"api/trace?x=300&y=0", "pixel (300, 0) is outside the 300×300 image of scenes/one-sphere.xml"},
                    {"api/trace?x=-1&y=0", "pixel (-1, 0) is outside"}}) {
                HttpResponse<String> r = get(explorer, c[0]);
                assertEquals(c[0], 400, r.statusCode());
                assertTrue(c[0] + ": " + r.body(), r.body().startsWith(c[1]));
                assertEquals(c[0] + " answers in one line", 1, r.body().lines().count());
            }
            HttpResponse<String> post = HTTP.send(HttpRequest.newBuilder(URI.create(explorer.url() + "api/trace?x=1&y=1"))
                    .POST(HttpRequest.BodyPublishers.noBody()).build(), HttpResponse.BodyHandlers.ofString());
            assertEquals(405, post.statusCode());
            assertEquals(405, get(explorer, "api/rerender").statusCode());
        }
    }

    /** Paths that try to leave the served set get a 404 and none of the files they name. */
    @Test(timeout = 120_000)
    public void nothingOutsideThePageAndTheApiIsServed() throws Exception {
        String readme = Files.readString(Path.of("README.md"));
        String gradle = Files.readString(Path.of("build.gradle"));
        try (Explorer explorer = Explorer.start(Path.of("scenes/one-sphere.xml"), null, 0)) {
            for (String path : List.of("../README.md", "%2e%2e/README.md", "%2e%2e%2fREADME.md", "api/../build.gradle",
                    "api/..%2f..%2fbuild.gradle", "explore.js/../../README.md", "ray/inspect/index.html", "scenes/one-sphere.xml",
                    "api/image.png/../../README.md", "..%5c..%5cREADME.md", "/etc/passwd", "api/reference.png%00.xml")) {
                HttpResponse<String> r = get(explorer, path);
                assertTrue(path + " → " + r.statusCode(), r.statusCode() == 404 || r.statusCode() == 400);
                assertFalse(path, r.body().contains(readme.substring(0, 40)) || r.body().contains(gradle.substring(0, 40)));
            }
            // A request for another host name (a DNS name pointed at 127.0.0.1 by a web page elsewhere) is refused.
            try (java.net.Socket socket = new java.net.Socket("127.0.0.1", explorer.port())) {
                socket.getOutputStream().write("GET /api/scene HTTP/1.1\r\nHost: evil.example:80\r\nConnection: close\r\n\r\n"
                        .getBytes(java.nio.charset.StandardCharsets.US_ASCII));
                String answer = new String(socket.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
                assertTrue(answer, answer.startsWith("HTTP/1.1 403"));
            }
            assertEquals(200, get(explorer, "").statusCode());
            assertTrue(get(explorer, "explore.js").body().length() > 100);
        }
    }

    /** Re-render reads the file again: an edit shows, a broken file answers 400 with its line and keeps the last image. */
    @Test(timeout = 120_000)
    public void reRenderReloadsTheSceneFile() throws Exception {
        Path scene = folder.getRoot().toPath().resolve("sphere.xml");
        String text = Files.readString(Path.of("scenes/one-sphere.xml")).replace("<image>300 300</image>", "<image>40 30</image>");
        Files.writeString(scene, text);
        try (Explorer explorer = Explorer.start(scene, null, 0)) {
            JsonObject first = json(explorer, "api/scene", 200);
            assertTrue("no reference beside a new scene", first.get("reference").isJsonNull());
            assertEquals(404, get(explorer, "api/reference.png").statusCode());
            assertEquals(404, get(explorer, "api/diff.png").statusCode());
            Files.writeString(scene, text.replace("0.2 0.3 0.8", "0.9 0.1 0.1"));
            HttpResponse<String> again = HTTP.send(HttpRequest.newBuilder(URI.create(explorer.url() + "api/rerender"))
                    .POST(HttpRequest.BodyPublishers.noBody()).build(), HttpResponse.BodyHandlers.ofString());
            assertEquals(200, again.statusCode());
            JsonObject second = JsonParser.parseString(again.body()).getAsJsonObject();
            assertEquals(first.get("renderId").getAsInt() + 1, second.get("renderId").getAsInt());
            List<Integer> red = ints(json(explorer, "api/trace?x=20&y=14", 200).getAsJsonArray("value"));
            assertTrue("the sphere is red now: " + red, red.get(0) > red.get(2));
            byte[] image = bytes(explorer, "api/image.png", 200);
            Files.writeString(scene, text.replace("<radius>1</radius>", "<radus>1</radus>"));
            HttpResponse<String> broken = HTTP.send(HttpRequest.newBuilder(URI.create(explorer.url() + "api/rerender"))
                    .POST(HttpRequest.BodyPublishers.noBody()).build(), HttpResponse.BodyHandlers.ofString());
            assertEquals(400, broken.statusCode());
            String error = JsonParser.parseString(broken.body()).getAsJsonObject().get("error").getAsString();
            assertTrue(error, error.startsWith(scene + ":") && error.contains("radus"));
            assertTrue("the last image stays", java.util.Arrays.equals(image, bytes(explorer, "api/image.png", 200)));
        }
    }

    /** A sphere whose intersect is still a stub that throws, as a student's may be. */
    public static class ThrowingSphere extends ray.surface.Sphere {
        @Override
        public boolean intersect(ray.IntersectionRecord out, ray.Ray ray) {
            throw new UnsupportedOperationException("TODO(Task 2)");
        }
    }

    /** The handout's stub camera: an empty segment, so nothing can be hit. */
    public static class StubCamera extends ray.camera.PerspectiveCamera {
        @Override
        public ray.Ray generateRay(double imageU, double imageV) {
            return new ray.Ray(viewPoint, w.negate(), 0, 0);
        }
    }

    /** Student code that throws, or a stub, shows where ray1 trace shows it: the render's error, the surface's entry, the camera's note. */
    @Test(timeout = 120_000)
    public void aThrowingSurfaceAndAStubCameraAreShownAsTheTraceShowsThem() throws Exception {
        String text = Files.readString(Path.of("scenes/one-sphere.xml")).replace("<image>300 300</image>", "<image>30 30</image>");
        Path throwing = folder.getRoot().toPath().resolve("throwing.xml");
        Files.writeString(throwing, text.replace("<surface type=\"Sphere\">", "<surface type=\"" + ThrowingSphere.class.getName() + "\">"));
        try (Explorer explorer = Explorer.start(throwing, null, 0)) {
            JsonObject summary = json(explorer, "api/scene", 200);
            String error = summary.get("renderError").getAsString();
            assertTrue(error, error.startsWith("the render failed: UnsupportedOperationException: TODO(Task 2) (at ExploreApiTest.java:"));
            HttpResponse<String> image = get(explorer, "api/image.png");
            assertEquals(404, image.statusCode());
            assertEquals(error + "\n", image.body());
            JsonObject story = json(explorer, "api/trace?x=15&y=15", 200);
            JsonObject sphere = story.getAsJsonArray("hits").get(0).getAsJsonObject();
            assertFalse(sphere.get("hit").getAsBoolean());
            assertTrue(sphere.toString(), sphere.get("error").getAsString().startsWith("threw UnsupportedOperationException: TODO(Task 2)"));
            assertTrue(story.toString(), story.get("value").isJsonNull());
            assertTrue(story.toString(), story.get("valueError").getAsString().startsWith("the renderer threw UnsupportedOperationException"));
            assertTrue(story.get("trace").getAsString(), story.get("trace").getAsString().contains("threw UnsupportedOperationException: TODO(Task 2)"));
        }
        Path stub = folder.getRoot().toPath().resolve("stub.xml");
        Files.writeString(stub, text.replace("<camera type=\"PerspectiveCamera\">", "<camera type=\"" + StubCamera.class.getName() + "\">"));
        try (Explorer explorer = Explorer.start(stub, null, 0)) {
            JsonObject summary = json(explorer, "api/scene", 200);
            String note = summary.getAsJsonArray("notes").get(0).getAsString();
            assertTrue(note, note.startsWith("the camera ray's segment is empty (start 0 = end 0), so nothing can be hit: ")
                    && note.contains("is still the stub? See TODO(Task 1)"));
            JsonObject story = json(explorer, "api/trace?x=15&y=15", 200);
            assertEquals(note, story.getAsJsonObject("cameraRay").get("problem").getAsString());
            assertTrue(story.get("closest").isJsonNull());
            assertEquals(List.of(0, 0, 0), ints(story.getAsJsonArray("value")));
        }
    }

    @Test(timeout = 60_000)
    public void theScenesWarningsComeFirstAmongTheNotesAfterEachRender() throws Exception {
        Path scene = folder.getRoot().toPath().resolve("box.xml");
        String text = """
                <scene>
                  <camera type="PerspectiveCamera"><viewPoint>0 0 5</viewPoint></camera>
                  <image>8 6</image>
                  <light><position>0 5 5</position><intensity>20 20 20</intensity></light>
                  <surface type="Box">
                    <minPt>-1 1 -1</minPt>
                    <maxPt>1 -1 1</maxPt>
                  </surface>
                </scene>
                """;
        Files.writeString(scene, text);
        String warning = scene + ":5:23: warning: Box minPt.y > maxPt.y; built from the corners as given, as the course's renderer does";
        try (Explorer explorer = Explorer.start(scene, null, 0)) {
            assertEquals(List.of(warning), explorer.warnings());
            JsonObject summary = json(explorer, "api/scene", 200);
            assertTrue(summary.get("renderError").isJsonNull());
            assertEquals(warning, summary.getAsJsonArray("notes").get(0).getAsString());
            // Edited to a flat box and rendered again: the page's notes say so, once.
            Files.writeString(scene, text.replace("<maxPt>1 -1 1</maxPt>", "<maxPt>1 1 1</maxPt>"));
            HttpResponse<String> again = HTTP.send(HttpRequest.newBuilder(URI.create(explorer.url() + "api/rerender"))
                    .POST(HttpRequest.BodyPublishers.noBody()).build(), HttpResponse.BodyHandlers.ofString());
            assertEquals(again.body(), 200, again.statusCode());
            JsonArray notes = JsonParser.parseString(again.body()).getAsJsonObject().getAsJsonArray("notes");
            assertEquals(notes.toString(), 1, notes.size());
            assertEquals(scene + ":5:23: warning: Box minPt.y = maxPt.y (a flat box); built from the corners as given, as the"
                    + " course's renderer does", notes.get(0).getAsString());
        }
    }

    private static String cli(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        try (PrintWriter o = new PrintWriter(out); PrintWriter e = new PrintWriter(err)) {
            assertEquals(String.join(" ", args) + ": " + err, 0, Ray1Command.run(o, e, args));
        }
        return out.toString();
    }

    private static HttpResponse<String> get(Explorer explorer, String path) throws Exception {
        return HTTP.send(HttpRequest.newBuilder(URI.create(explorer.url() + path)).build(), HttpResponse.BodyHandlers.ofString());
    }

    private static JsonObject json(Explorer explorer, String path, int status) throws Exception {
        HttpResponse<String> r = get(explorer, path);
        assertEquals(path + ": " + r.body(), status, r.statusCode());
        return JsonParser.parseString(r.body()).getAsJsonObject();
    }

    private static byte[] bytes(Explorer explorer, String path, int status) throws Exception {
        HttpResponse<byte[]> r = HTTP.send(HttpRequest.newBuilder(URI.create(explorer.url() + path)).build(),
                HttpResponse.BodyHandlers.ofByteArray());
        assertEquals(path, status, r.statusCode());
        return r.body();
    }

    private static List<Integer> ints(JsonArray a) {
        List<Integer> list = new ArrayList<>();
        a.forEach(e -> list.add(e.getAsInt()));
        return list;
    }

    private static void assertVec(double[] expected, JsonArray actual, double tolerance) {
        for (int k = 0; k < 3; k++) {
            assertEquals("component " + k + " of " + actual, expected[k], actual.get(k).getAsDouble(), tolerance);
        }
    }
}
