package ray.scene;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.surface.MeshData;

/**
 * Checks what {@link ObjReader} makes of valid OBJ text: positions and normals, faces in every
 * index form, negative indices, polygons split into fans around their first vertex (exact index
 * arrays), the statements and comments it ignores (comments in any bytes), a UTF-8 byte order mark,
 * and the -1 marker of faces without normals.
 */
public class ObjReaderTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    /** Three vertices, three texture coordinates and three normals, for the faces of the tests below. */
    private static final String TRIANGLE = """
            v 0 0 0
            v 1 0 0
            v 0 1 0
            vt 0 0
            vt 1 0
            vt 0 1
            vn 0 0 1
            vn 0 1 0
            vn 1 0 0
            """;

    @Test
    public void readsPositionsAndNormalsInOrder() {
        MeshData mesh = read("""
                v 1 2 3
                v -4.5 5e-1 +6
                vn 0 0 1
                vn 0.6 0.8 0
                f 1 2 1
                """);
        assertArrayEquals(new double[] {1, 2, 3, -4.5, 0.5, 6}, mesh.positions, 0);
        assertArrayEquals(new double[] {0, 0, 1, 0.6, 0.8, 0}, mesh.normals, 0);
        assertEquals(2, mesh.vertexCount());
        assertEquals(1, mesh.triangleCount());
    }

    @Test
    public void everyFaceIndexFormNamesTheSameVertices() {
        MeshData mesh = read(TRIANGLE + """
                f 1 2 3
                f 1/1 2/2 3/3
                f 1//3 2//2 3//1
                f 1/1/3 2/2/2 3/3/1
                """);
        assertArrayEquals(new int[] {0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2}, mesh.triangles);
        // Only the last two faces carry normals (the OBJ's third, second and first).
        assertArrayEquals(new int[] {-1, -1, -1, -1, -1, -1, 2, 1, 0, 2, 1, 0}, mesh.triangleNormals);
    }

    @Test
    public void negativeIndicesCountBackFromTheLatestDefinition() {
        MeshData mesh = read(TRIANGLE + """
                f -3//-1 -2//-2 -1//-3
                v 1 1 0
                f -1 -2 -3
                """);
        // Before the fourth vertex, -1 is vertex 3 (index 2); after it, -1 is vertex 4 (index 3).
        assertArrayEquals(new int[] {0, 1, 2, 3, 2, 1}, mesh.triangles);
        assertArrayEquals(new int[] {2, 1, 0, -1, -1, -1}, mesh.triangleNormals);
    }

    @Test
    public void quadSplitsIntoTwoTrianglesAroundItsFirstVertex() {
        MeshData mesh = read("""
                v 0 0 0
                v 1 0 0
                v 1 1 0
                v 0 1 0
                f 1 2 3 4
                """);
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, mesh.triangles);
        assertNull("no face has normals", mesh.triangleNormals);
    }

    @Test
    public void pentagonSplitsIntoAFanWithMatchingNormals() {
        MeshData mesh = read("""
                v 0 0 0
                v 2 0 0
                v 3 1 0
                v 1 2 0
                v -1 1 0
                vn 0 0 1
                vn 0 0 1
                vn 0 0 1
                vn 0 0 1
                vn 0 0 1
                f 2//5 3//4 4//3 5//2 1//1
                """);
        // Fan around the first corner (vertex 2, normal 5): (2 3 4), (2 4 5), (2 5 1), zero-based.
        assertArrayEquals(new int[] {1, 2, 3, 1, 3, 4, 1, 4, 0}, mesh.triangles);
        assertArrayEquals(new int[] {4, 3, 2, 4, 2, 1, 4, 1, 0}, mesh.triangleNormals);
    }

    @Test
    public void groupingMaterialStatementsAndCommentsAreIgnored() {
        MeshData mesh = read("""
                # exported by a modeler
                mtllib scene.mtl
                o Thing
                g part1 part2

                   v 0 0 0   # leading white space and a trailing comment
                v 1 0 0
                v\t0\t1\t0
                usemtl red
                s 1
                s off
                l 1 2
                # f 3 2 1
                f 1 2 3 # the only face
                """);
        assertArrayEquals(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, mesh.positions, 0);
        assertArrayEquals(new int[] {0, 1, 2}, mesh.triangles);
    }

    @Test
    public void vertexWeightAfterXyzIsAcceptedAndIgnored() {
        MeshData mesh = read("""
                v 1 2 3 0.5
                v 4 5 6 1
                v 7 8 9 1
                f 1 2 3
                """);
        assertArrayEquals(new double[] {1, 2, 3, 4, 5, 6, 7, 8, 9}, mesh.positions, 0);
    }

    @Test
    public void facesWithoutNormalsAreMarkedMinusOneWhenOthersHaveThem() {
        MeshData mesh = read(TRIANGLE + """
                v 1 1 0
                f 1//1 2//1 3//1
                f 2 4 3
                f 2//2 4 3//2
                """);
        // The third face has a normal on only two corners: the whole face counts as without normals.
        assertArrayEquals(new int[] {0, 1, 2, 1, 3, 2, 1, 3, 2}, mesh.triangles);
        assertArrayEquals(new int[] {0, 0, 0, -1, -1, -1, -1, -1, -1}, mesh.triangleNormals);
    }

    @Test
    public void windowsLineEndingsAreAccepted() {
        MeshData mesh = read("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n");
        assertArrayEquals(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, mesh.positions, 0);
        assertArrayEquals(new int[] {0, 1, 2}, mesh.triangles);
    }

    @Test
    public void byteOrderMarkAndUtf8TextAreAccepted() {
        MeshData mesh = read("\uFEFFv 0 0 0\nv 1 0 0\nv 0 1 0\ng Schädel # für Übungen\nf 1 2 3\n");
        assertArrayEquals("the first vertex is read, not skipped", new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, mesh.positions, 0);
        assertArrayEquals(new int[] {0, 1, 2}, mesh.triangles);
    }

    @Test
    public void commentsMayHoldBytesThatAreNotUtf8() {
        // Comments written in Latin-1 ("é" as the single byte 0xE9) are skipped like any other.
        Path file = folder.getRoot().toPath().resolve("latin1.obj");
        try {
            Files.write(file, ObjReaderErrorsTest.bytes("# caf", 0xE9, "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 # ", 0xFF, "\n"));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        assertArrayEquals(new int[] {0, 1, 2}, ObjReader.read(file).triangles);
    }

    private MeshData read(String obj) {
        return ObjReader.read(SceneFixtures.write(folder, "mesh.obj", obj));
    }
}
