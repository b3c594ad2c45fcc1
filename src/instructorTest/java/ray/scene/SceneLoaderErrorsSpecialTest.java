package ray.scene;

import static org.junit.Assert.assertFalse;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * Checks the scene errors that do not fit {@link SceneLoaderErrorsTest}'s table of one scene text
 * and its error: mesh files that are missing, folders, empty, unreadable or broken (the error then
 * names the OBJ file and its line), a transform that cannot be inverted (its mesh file beside the
 * scene), scene files that are missing, folders, unreadable or not UTF-8, and the refusal of any
 * DOCTYPE (so no entity can expand without bound or read a local file). Each error is checked whole:
 * the file, line and column, what is wrong and what was expected.
 *
 * <p>SAX locates an element where its start tag ends, so an element's column is the one just after
 * its {@code >}; each element sits on its own line so that the line is unambiguous.
 */
public class SceneLoaderErrorsSpecialTest {
    private static final String DOCTYPE_REFUSED =
            "a DOCTYPE is not allowed in a scene file; expected plain XML, without entities or external files";

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void missingMeshFileIsReportedAtItsDataElement() {
        Path scene = SceneFixtures.write(folder, "scenes/mesh.xml", """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Mesh">
                    <data>../meshes/nope.obj</data>
                  </surface>
                </scene>
                """);
        Path resolved = folder.getRoot().toPath().toAbsolutePath().resolve("meshes/nope.obj");
        SceneFixtures.assertError(SceneFixtures.loadError(scene), scene, 5, 11, "no such mesh file " + resolved
                + "; expected an OBJ file (a relative path in <data> starts from the scene file's folder, or the nearest folder above it that has the file)");
    }

    @Test
    public void errorInAMeshFileNamesTheObjFileAndItsLine() {
        Path obj = SceneFixtures.write(folder, "meshes/broken.obj", """
                v 0 0 0
                v 1 0 0
                f 1 2 3
                """);
        SceneException e = SceneFixtures.loadError(meshScene("meshes/broken.obj"));
        SceneFixtures.assertError(e, obj.toAbsolutePath().normalize(), 3, 1,
                "vertex index 3 is out of range; expected 1 to 2 or -1 to -2 (2 defined so far)");
    }

    @Test
    public void meshPathThatIsAFolderIsReportedAtItsDataElement() throws Exception {
        Path meshes = Files.createDirectories(folder.getRoot().toPath().resolve("meshes"));
        Path scene = meshScene("meshes");
        SceneFixtures.assertError(SceneFixtures.loadError(scene), scene, 5, 11,
                "the mesh path " + meshes.toAbsolutePath() + " is a folder; expected an OBJ file");
    }

    @Test
    public void emptyMeshFileIsReportedInThatFile() {
        Path obj = SceneFixtures.write(folder, "empty.obj", "");
        SceneException e = SceneFixtures.loadError(meshScene("empty.obj"));
        SceneFixtures.assertError(e, obj.toAbsolutePath(), 1, 1, "the mesh file is empty; expected 'v' and 'f' lines");
    }

    @Test
    public void unreadableMeshFileIsReportedInThatFile() {
        Path obj = SceneFixtures.write(folder, "locked.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        String reason = SceneFixtures.makeUnreadable(obj);
        SceneException e = SceneFixtures.loadError(meshScene("locked.obj"));
        SceneFixtures.assertError(e, obj.toAbsolutePath(), 1, 1,
                "the file cannot be read (" + reason + "); expected a readable OBJ file");
    }

    /** Found by the fuzzer: no factor is zero, but their product overflows, so the transform has no inverse. */
    @Test
    public void scaleWhoseProductOverflowsIsRefused() {
        SceneFixtures.write(folder, "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Mesh">
                    <data>m.obj</data>
                    <scale>5 5 1.7976931348623157e308</scale>
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(e, folder.getRoot().toPath().resolve("bad.xml"), 4, 24, "invalid Mesh: the transform"
                + " cannot be inverted (its determinant is Infinity); expected scales and rotations whose product is nonzero and finite");
    }

    @Test
    public void bytesThatAreNotUtf8AreReportedWhereTheyAre() {
        Path file = SceneFixtures.write(folder, "latin1.xml", "<scene>\n  <image>4 3</image> <!-- gr\u00f6\u00dfe -->\n</scene>\n"
                .getBytes(StandardCharsets.ISO_8859_1));
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 2, 29,
                "malformed XML: this is not UTF-8 text; expected a scene file saved as UTF-8 (or ASCII), not as Latin-1 or Windows-1252");
    }

    @Test
    public void missingFileIsReportedWithItsName() {
        Path file = folder.getRoot().toPath().resolve("nowhere.xml");
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 1, 1, "no such file; expected the path of a scene file");
    }

    @Test
    public void folderIsNotASceneFile() throws Exception {
        Path scenes = Files.createDirectories(folder.getRoot().toPath().resolve("scenes.xml"));
        SceneFixtures.assertError(SceneFixtures.loadError(scenes), scenes, 1, 1, "this is a folder; expected a scene file");
    }

    @Test
    public void unreadableFileIsReportedAsSuch() {
        Path file = SceneFixtures.write(folder, "locked.xml", "<scene/>\n");
        String reason = SceneFixtures.makeUnreadable(file);
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 1, 1,
                "the file cannot be read (" + reason + "); expected a readable scene file");
    }

    @Test(timeout = 10_000)
    public void billionLaughsFailsFastOnItsDoctype() {
        // Ten levels of ten references each would expand to 10¹⁰ "lol"s if the parser took the DOCTYPE.
        StringBuilder xml = new StringBuilder("<?xml version=\"1.0\"?>\n<!DOCTYPE scene [\n  <!ENTITY lol0 \"lol\">\n");
        for (int level = 1; level <= 10; level++) {
            xml.append("  <!ENTITY lol").append(level).append(" \"");
            for (int k = 0; k < 10; k++) {
                xml.append("&lol").append(level - 1).append(';');
            }
            xml.append("\">\n");
        }
        xml.append("]>\n<scene>\n  <exposure>&lol10;</exposure>\n</scene>\n");
        Path file = SceneFixtures.write(folder, "lol.xml", xml.toString());
        // Located at "<!DOCTYPE" on line 2, just past the keyword.
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 2, 10, DOCTYPE_REFUSED);
    }

    @Test
    public void externalEntityIsRefusedAndTheFileItNamesNeverAppears() {
        Path secret = SceneFixtures.write(folder, "secret.txt", "TOP-SECRET-42");
        Path file = SceneFixtures.write(folder, "xxe.xml", "<?xml version=\"1.0\"?>\n"
                + "<!DOCTYPE scene [\n"
                + "  <!ENTITY secret SYSTEM \"" + secret.toUri() + "\">\n"
                + "]>\n"
                + "<scene>\n"
                + "  <camera type=\"PerspectiveCamera\"/>\n"
                + "  <image>4 3</image>\n"
                // Were the entity expanded, the secret would come back in the "not a number" error.
                + "  <exposure>&secret;</exposure>\n"
                + "</scene>\n");
        SceneException e = SceneFixtures.loadError(file);
        SceneFixtures.assertError(e, file, 2, 10, DOCTYPE_REFUSED);
        assertFalse(e.getMessage(), e.getMessage().contains("TOP-SECRET"));
    }

    /** A scene file, mesh.xml, whose line 5 is {@code <data>dataText</data>} in a Mesh. */
    private Path meshScene(String dataText) {
        return SceneFixtures.write(folder, "mesh.xml", """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Mesh">
                    <data>%s</data>
                  </surface>
                </scene>
                """.formatted(dataText));
    }
}
