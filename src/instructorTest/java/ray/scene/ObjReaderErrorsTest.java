package ray.scene;

import static org.junit.Assert.assertThrows;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * Checks that a bad OBJ file raises a {@link SceneException} naming the OBJ file and its own line
 * number (column 1: OBJ statements are one per line), with the problem and what was expected, each
 * message checked whole: words, special values and bytes that are not UTF-8 text where numbers
 * belong, too few values, indices out of range, faces with fewer than 3 vertices, files that are
 * missing, folders or empty.
 */
public class ObjReaderErrorsTest {
    private static final String NOT_UTF8 = " is not UTF-8 text; expected OBJ text in UTF-8 (or ASCII)";

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void wordInACoordinateIsNotANumber() {
        assertObjError("""
                v 0 0 0
                v 1 abc 0
                """, 2, "\"abc\" is not a number; expected v x y z");
    }

    @Test
    public void controlCharactersAndLineSeparatorsAreQuotedAsEscapes() {
        // The message stays one readable line whatever the word holds.
        assertObjError("v 0 1\u00072 0\n", 1, "\"1\\u00072\" is not a number; expected v x y z");
        assertObjError("v 0 1\u20282 0\n", 1, "\"1\\u20282\" is not a number; expected v x y z");
    }

    @Test
    public void nanAndOverflowingCoordinatesAreNotFinite() {
        assertObjError("v 0 NaN 0\n", 1, "\"NaN\" is not a finite number; expected v x y z");
        assertObjError("v 0 0 Infinity\n", 1, "\"Infinity\" is not a finite number; expected v x y z");
        assertObjError("v 0 0 0\nvn 1e999 0 0\n", 2, "\"1e999\" is not a finite number; expected vn x y z");
    }

    @Test
    public void vertexWithTwoCoordinatesAsksForThree() {
        assertObjError("""
                # a comment counts as a line
                v 1 2
                """, 2, "'v' has 2 numbers; expected v x y z");
    }

    @Test
    public void texCoordWithoutValuesAsksForOne() {
        assertObjError("v 0 0 0\nvt\n", 2, "'vt' has no coordinates; expected vt u [v [w]]");
    }

    @Test
    public void faceWithTwoVerticesIsRefused() {
        assertObjError("""
                v 0 0 0
                v 1 0 0

                f 1 2
                """, 4, "the face has 2 vertices; expected at least 3: f v1 v2 v3 ...");
        assertObjError("v 0 0 0\nf 1\n", 2, "the face has 1 vertex; expected at least 3: f v1 v2 v3 ...");
        assertObjError("v 0 0 0\nf\n", 2, "the face has no vertices; expected at least 3: f v1 v2 v3 ...");
    }

    @Test
    public void vertexIndexPastTheLastVertexIsOutOfRange() {
        assertObjError("""
                v 0 0 0
                v 1 0 0
                v 0 1 0
                f 1 2 4
                """, 4, "vertex index 4 is out of range; expected 1 to 3 or -1 to -3 (3 defined so far)");
    }

    @Test
    public void negativeIndexBeforeTheFirstVertexIsOutOfRange() {
        assertObjError("""
                v 0 0 0
                v 1 0 0
                v 0 1 0
                f -4 1 2
                """, 4, "vertex index -4 is out of range; expected 1 to 3 or -1 to -3 (3 defined so far)");
    }

    @Test
    public void indexZeroIsOutOfRange() {
        assertObjError("""
                v 0 0 0
                v 1 0 0
                v 0 1 0
                f 0 1 2
                """, 4, "vertex index 0 is out of range; expected 1 to 3 or -1 to -3 (3 defined so far)");
    }

    @Test
    public void faceBeforeAnyVertexSaysNoneIsDefinedYet() {
        assertObjError("""
                f 1 2 3
                v 0 0 0
                v 1 0 0
                v 0 1 0
                """, 1, "vertex index 1 is out of range; expected a vertex defined on an earlier line (none is defined so far)");
    }

    @Test
    public void normalAndTexCoordIndicesAreCheckedToo() {
        assertObjError("""
                v 0 0 0
                v 1 0 0
                v 0 1 0
                vn 0 0 1
                f 1//1 2//2 3//1
                """, 5, "normal index 2 is out of range; expected 1 to 1 or -1 to -1 (1 defined so far)");
        assertObjError("""
                v 0 0 0
                v 1 0 0
                v 0 1 0
                f 1/1 2/1 3/1
                """, 4, "texture coordinate index 1 is out of range;"
                + " expected a texture coordinate defined on an earlier line (none is defined so far)");
    }

    @Test
    public void fractionalIndexIsNotAnIndex() {
        assertObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1.5 2 3\n", 4, "\"1.5\" is not a vertex index; expected an integer");
    }

    @Test
    public void malformedFaceVertexIsRefused() {
        assertObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", 4,
                "\"1/1/1/1\" is not a face vertex; expected v, v/vt, v//vn or v/vt/vn");
        assertObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf /1 2 3\n", 4,
                "\"/1\" is not a face vertex; expected v, v/vt, v//vn or v/vt/vn");
    }

    @Test
    public void emptyFileIsReportedAsEmpty() {
        assertObjError("", 1, "the mesh file is empty; expected 'v' and 'f' lines");
    }

    @Test
    public void verticesWithoutFacesAreReportedAtTheEndOfTheFile() {
        assertObjError("""
                v 0 0 0
                v 1 0 0
                v 0 1 0
                """, 3, "the mesh has no faces; expected at least one 'f' line");
    }

    @Test
    public void lineNumbersCountWindowsLineEndingsOnce() {
        assertObjError("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 9\r\n", 4,
                "vertex index 9 is out of range; expected 1 to 3 or -1 to -3 (3 defined so far)");
    }

    @Test
    public void bytesThatAreNotUtf8InAStatementAreReportedAtTheirLine() {
        // 0xFF never occurs in UTF-8 text; a Latin-1 "é" (0xE9) followed by a space is not UTF-8 either.
        assertObjBytesError(bytes("v 0 0 0\nv 1 ", 0xFF, " 0\n"), 2, "byte 0xFF" + NOT_UTF8);
        assertObjBytesError(bytes("v 0 0 0\ng caf", 0xE9, " 1\n"), 2, "byte 0xE9" + NOT_UTF8);
    }

    @Test
    public void binaryFileIsReportedAtItsFirstLine() {
        // A PNG file begins with 0x89 "PNG" CR LF.
        assertObjBytesError(bytes("", 0x89, "PNG\r\n", 0x1A, "\n"), 1, "byte 0x89" + NOT_UTF8);
    }

    @Test
    public void missingFileIsReportedWithItsName() {
        Path missing = folder.getRoot().toPath().resolve("missing.obj");
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.read(missing));
        SceneFixtures.assertError(e, missing, 1, 1, "no such file; expected the path of an OBJ file");
    }

    @Test
    public void folderIsNotAnObjFile() throws IOException {
        Path meshes = Files.createDirectories(folder.getRoot().toPath().resolve("meshes"));
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.read(meshes));
        SceneFixtures.assertError(e, meshes, 1, 1, "this is a folder; expected an OBJ file");
    }

    /** Checks that reading {@code obj} fails at {@code line}, column 1, of that file, with exactly {@code problem}. */
    private void assertObjError(String obj, int line, String problem) {
        assertObjBytesError(obj.getBytes(StandardCharsets.UTF_8), line, problem);
    }

    private void assertObjBytesError(byte[] obj, int line, String problem) {
        Path file = folder.getRoot().toPath().resolve("mesh.obj");
        try {
            Files.write(file, obj);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.read(file));
        SceneFixtures.assertError(e, file, line, 1, problem);
    }

    /** The bytes of the pieces in order: each string as ASCII, each Integer as one byte. */
    static byte[] bytes(Object... pieces) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (Object piece : pieces) {
            if (piece instanceof Integer) {
                out.write((Integer) piece);
            } else {
                out.writeBytes(((String) piece).getBytes(StandardCharsets.US_ASCII));
            }
        }
        return out.toByteArray();
    }
}
