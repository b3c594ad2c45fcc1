package ray.scene;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.image.PngWriter;
import ray.render.Renderer;
import ray.surface.MeshData;
import ray.testing.ProjectFolder;

/**
 * The shipped scenes as a Windows student's copy has them: every XML and OBJ file with CRLF line
 * ends (what git's autocrlf and Windows editors write), in a folder whose path has spaces ("my
 * scenes/ray one/"), and some with a UTF-8 byte order mark (Notepad's "UTF-8 with BOM") or with a
 * space in a mesh's or texture's file name. Each renders pixel for pixel as the shipped file does,
 * with the renderer the render tests use, and a mistake in such a file is reported at the same line
 * and column as in the shipped one.
 */
public class WindowsStyleScenesTest {
    @ClassRule
    public static final TemporaryFolder TEMPORARY = new TemporaryFolder();

    private static final byte[] UTF8_BOM = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};
    /** The shipped scenes folder, and its CRLF copy under a path with spaces. */
    private static Path shipped;
    private static Path copy;
    /** Renders of the shipped scenes, by path under scenes/, made once for the tests that compare with them. */
    private static final Map<String, BufferedImage> ORIGINALS = new HashMap<>();

    @BeforeClass
    public static void copyTheScenesWithCrlfIntoAPathWithSpaces() throws IOException {
        shipped = ProjectFolder.resolve("scenes");
        copy = TEMPORARY.getRoot().toPath().resolve("my scenes").resolve("ray one").resolve("scenes");
        try (Stream<Path> walk = Files.walk(shipped)) {
            for (Path file : walk.filter(Files::isRegularFile).collect(Collectors.toList())) {
                Path relative = shipped.relativize(file);
                if (relative.startsWith("reference")) {
                    continue;
                }
                Path target = copy.resolve(relative.toString());
                Files.createDirectories(target.getParent());
                String name = file.getFileName().toString();
                if (name.endsWith(".xml") || name.endsWith(".obj")) {
                    Files.write(target, crlf(Files.readAllBytes(file)));
                } else {
                    Files.copy(file, target);
                }
            }
        }
    }

    /**
     * The bytes with every line ending in CRLF. The shipped files end lines in LF alone (checked, so
     * that this test really reads CRLF files); bytes are kept as Latin-1 characters, one for one.
     */
    private static byte[] crlf(byte[] bytes) {
        String text = new String(bytes, StandardCharsets.ISO_8859_1);
        assertFalse("a shipped file already has a CR", text.contains("\r"));
        assertTrue("a shipped file has no line end", text.contains("\n"));
        return text.replace("\n", "\r\n").getBytes(StandardCharsets.ISO_8859_1);
    }

    private static String text(Path file) throws IOException {
        return Files.readString(file, StandardCharsets.UTF_8);
    }

    private static Path writeText(Path file, String text) throws IOException {
        Files.createDirectories(file.getParent());
        return Files.write(file, text.getBytes(StandardCharsets.UTF_8));
    }

    /** A scene at its full size as 8-bit pixels, as the render tests make it (RenderScenes.render). */
    private static BufferedImage render(Path sceneFile) {
        Scene scene = SceneLoader.load(sceneFile);
        return PngWriter.toBufferedImage(new Renderer(scene, 0, 0).render().image, scene.getExposure());
    }

    private static BufferedImage original(String scene) {
        return ORIGINALS.computeIfAbsent(scene, s -> render(shipped.resolve(s)));
    }

    /** Every pixel the same, or the first one that is not. */
    private static void assertSamePixels(String what, BufferedImage expected, BufferedImage actual) {
        assertEquals(what + ": width", expected.getWidth(), actual.getWidth());
        assertEquals(what + ": height", expected.getHeight(), actual.getHeight());
        for (int y = 0; y < expected.getHeight(); y++) {
            for (int x = 0; x < expected.getWidth(); x++) {
                if (expected.getRGB(x, y) != actual.getRGB(x, y)) {
                    fail(String.format("%s: pixel (%d, %d) is %06x, the shipped scene's is %06x", what, x, y,
                            actual.getRGB(x, y) & 0xffffff, expected.getRGB(x, y) & 0xffffff));
                }
            }
        }
    }

    private static void assertRendersLikeTheShipped(String scene, Path file) {
        assertSamePixels(file.toString(), original(scene), render(file));
    }

    @Test
    public void theCopyIsCrlfInAPathWithSpaces() throws IOException {
        Path sphere = copy.resolve("one-sphere.xml");
        assertTrue(sphere.toString(), sphere.toString().contains("my scenes" + sphere.getFileSystem().getSeparator() + "ray one"));
        String xml = text(sphere);
        String obj = text(copy.resolve("meshes/vase.obj"));
        for (String t : List.of(xml, obj)) {
            assertEquals("every line end is CRLF", t.split("\n", -1).length, t.split("\r\n", -1).length);
        }
    }

    @Test
    public void aPlainSphereScene() {
        assertRendersLikeTheShipped("one-sphere.xml", copy.resolve("one-sphere.xml"));
    }

    @Test
    public void aMeshWithVertexNormals() {
        // torus-smooth.obj: f v//vn faces, so the normals are read from vn lines.
        assertRendersLikeTheShipped("mesh-smooth.xml", copy.resolve("mesh-smooth.xml"));
    }

    @Test
    public void meshesWithNormalsAndTextureCoordinatesAndTexturesByRelativePaths() {
        // The vase (f v/vt/vn) and the tablecloth (f v/vt), with two PNG textures, all named by ../ paths.
        assertRendersLikeTheShipped("textured/tablecloth.xml", copy.resolve("textured/tablecloth.xml"));
    }

    @Test
    public void aCrlfMeshReadsTheSameNumbers() {
        // Stronger than the picture: every coordinate and index of the OBJ file, with all three kinds of line.
        MeshData lf = ObjReader.read(shipped.resolve("meshes/vase.obj"));
        MeshData crlf = ObjReader.read(copy.resolve("meshes/vase.obj"));
        assertTrue("vase.obj has normals and texture coordinates", lf.normals.length > 0 && lf.texCoords.length > 0);
        assertArrayEquals(lf.positions, crlf.positions, 0);
        assertArrayEquals(lf.normals, crlf.normals, 0);
        assertArrayEquals(lf.texCoords, crlf.texCoords, 0);
        assertArrayEquals(lf.triangles, crlf.triangles);
        assertArrayEquals(lf.triangleNormals, crlf.triangleNormals);
        assertArrayEquals(lf.triangleTexCoords, crlf.triangleTexCoords);
    }

    @Test
    public void aTexturedSphere() {
        assertRendersLikeTheShipped("textured/globe.xml", copy.resolve("textured/globe.xml"));
    }

    @Test
    public void meshAndTextureFileNamesWithSpaces() throws IOException {
        // Copies of the vase and its flower under names with spaces, and the scene edited to name them.
        Files.copy(copy.resolve("meshes/vase.obj"), copy.resolve("meshes/flower vase.obj"));
        Files.copy(copy.resolve("textures/flower.png"), copy.resolve("textures/pressed flower.png"));
        String xml = text(copy.resolve("textured/tablecloth.xml"));
        String edited = xml.replace("<data>../meshes/vase.obj</data>", "<data>../meshes/flower vase.obj</data>")
                .replace("<image>../textures/flower.png</image>", "<image>../textures/pressed flower.png</image>");
        assertTrue(edited, edited.contains("flower vase.obj") && edited.contains("pressed flower.png"));
        Path scene = writeText(copy.resolve("textured/tablecloth with spaces.xml"), edited);
        assertRendersLikeTheShipped("textured/tablecloth.xml", scene);
    }

    @Test
    public void aByteOrderMarkBeforeTheXmlAndTheObj() throws IOException {
        // Notepad's "UTF-8 with BOM": the XML parser and the OBJ reader both skip the mark.
        Path obj = copy.resolve("meshes/vase with bom.obj");
        Files.write(obj, concat(UTF8_BOM, Files.readAllBytes(copy.resolve("meshes/vase.obj"))));
        String xml = text(copy.resolve("textured/tablecloth.xml")).replace("../meshes/vase.obj", "../meshes/vase with bom.obj");
        Path scene = copy.resolve("textured/tablecloth with bom.xml");
        Files.write(scene, concat(UTF8_BOM, xml.getBytes(StandardCharsets.UTF_8)));
        assertTrue(xml, xml.startsWith("<?xml"));
        assertRendersLikeTheShipped("textured/tablecloth.xml", scene);
    }

    /**
     * A misspelled element in a CRLF scene: the line and column are where the shipped file has it
     * (the column just after the start tag's {@code >}, where SAX locates an element), and the file
     * is named with its spaces.
     */
    @Test
    public void aMistakeInACrlfSceneIsReportedAtItsLineAndColumn() throws IOException {
        String shippedText = text(shipped.resolve("one-sphere.xml"));
        int[] at = lineAndColumnAfter(shippedText, "<radius>");
        Path scene = writeText(copy.resolve("misspelled.xml"),
                text(copy.resolve("one-sphere.xml")).replace("<radius>1</radius>", "<radus>1</radus>"));
        SceneException e = loadError(scene);
        assertEquals(e.getMessage(), at[0], e.line());
        // "<radus>" is one character shorter than "<radius>".
        assertEquals(e.getMessage(), at[1] - 1, e.column());
        assertTrue(e.getMessage(), e.getMessage().startsWith(scene + ":" + at[0] + ":" + (at[1] - 1)
                + ": unknown element <radus> in a Sphere (did you mean <radius>?)"));
        assertSameErrorAsLf(shippedText.replace("<radius>1</radius>", "<radus>1</radus>"), e);
    }

    /**
     * Malformed XML in a CRLF scene: an element that is never closed is found in the file's text
     * (the parser reports only where it stopped), so the count of CRLF line ends is the loader's own.
     */
    @Test
    public void anUnclosedElementInACrlfSceneIsReportedWhereItStarts() throws IOException {
        String shippedText = text(shipped.resolve("one-sphere.xml"));
        String sphere = "<surface type=\"Sphere\">";
        int[] at = lineAndColumnAfter(shippedText, sphere);
        Path scene = writeText(copy.resolve("unclosed.xml"), text(copy.resolve("one-sphere.xml")).replace("</surface>", ""));
        SceneException e = loadError(scene);
        assertEquals(e.getMessage(), at[0], e.line());
        // Where "<surface" starts: its '<'.
        assertEquals(e.getMessage(), at[1] - sphere.length(), e.column());
        assertTrue(e.getMessage(), e.problem().startsWith("malformed XML: <surface> is never closed"));
        assertSameErrorAsLf(shippedText.replace("</surface>", ""), e);
    }

    /** A bad face in a CRLF mesh: the error names the OBJ file (with its spaces) and its own line. */
    @Test
    public void aMistakeInACrlfMeshIsReportedAtItsLine() throws IOException {
        Path obj = copy.resolve("meshes/torus-smooth.obj");
        List<String> lines = new ArrayList<>(List.of(text(obj).split("\r\n", -1)));
        int face = lines.indexOf(lines.stream().filter(l -> l.startsWith("f ")).findFirst().orElseThrow());
        // Past the comment and v and vn lines, so the count of CRLF lines before it matters.
        assertTrue("the first face is on line " + (face + 1), face > 100);
        lines.set(face, "f 1//1 2//2 99999//3");
        Path broken = writeText(copy.resolve("meshes/broken torus.obj"), String.join("\r\n", lines));
        Path scene = writeText(copy.resolve("broken-mesh.xml"),
                text(copy.resolve("mesh-smooth.xml")).replace("meshes/torus-smooth.obj", "meshes/broken torus.obj"));
        SceneException e = loadError(scene);
        assertEquals(e.getMessage(), broken, e.file());
        assertEquals(e.getMessage(), face + 1, e.line());
        assertEquals(e.getMessage(), 1, e.column());
        assertTrue(e.getMessage(), e.problem().startsWith("vertex index 99999 is out of range"));
    }

    private static SceneException loadError(Path scene) {
        try {
            SceneLoader.load(scene);
        } catch (SceneException e) {
            return e;
        }
        throw new AssertionError(scene + " loaded, but it has a mistake");
    }

    /** The same mistake in an LF file (the shipped line ends) is reported at the same place, in the same words. */
    private static void assertSameErrorAsLf(String lfText, SceneException crlfError) throws IOException {
        assertFalse(lfText.contains("\r"));
        SceneException lf = loadError(writeText(TEMPORARY.getRoot().toPath().resolve("lf").resolve("scene.xml"), lfText));
        assertEquals(lf.line() + ":" + lf.column() + ": " + lf.problem(),
                crlfError.line() + ":" + crlfError.column() + ": " + crlfError.problem());
    }

    /** The 1-based line of the first {@code marker} in {@code text} (LF line ends), and the column just after it. */
    private static int[] lineAndColumnAfter(String text, String marker) {
        int offset = text.indexOf(marker);
        assertTrue("no " + marker, offset >= 0);
        int lineStart = text.lastIndexOf('\n', offset) + 1;
        int line = (int) text.substring(0, lineStart).chars().filter(c -> c == '\n').count() + 1;
        return new int[] {line, offset - lineStart + marker.length() + 1};
    }

    private static byte[] concat(byte[] a, byte[] b) {
        byte[] both = new byte[a.length + b.length];
        System.arraycopy(a, 0, both, 0, a.length);
        System.arraycopy(b, 0, both, a.length, b.length);
        return both;
    }
}
