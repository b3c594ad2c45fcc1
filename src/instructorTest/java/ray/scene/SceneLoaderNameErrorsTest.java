package ray.scene;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * Checks errors in names: unknown elements, types and attributes (with a "did you mean" when a known
 * name is close), a missing type, refs that name something later, the object they are in or the
 * wrong kind of object (refs that name nothing: {@link SceneLoaderRefErrorsTest}), a name used
 * twice, and mesh files that are missing, folders, empty or unreadable. Each error is checked whole:
 * the file, line and column, what is wrong and what was expected.
 *
 * <p>SAX locates an element where its start tag ends, so an element's column is the one just after
 * its {@code >}; each element sits on its own line so that the line is unambiguous.
 */
public class SceneLoaderNameErrorsTest {
    private static final String SURFACE_TYPES = "Sphere, Triangle, Box, Mesh, Cylinder, Group";
    private static final String SHADER_TYPES = "Lambertian, Phong, RGBNormals, Glazed";

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void misspelledPropertySuggestsTheClosestOne() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Sphere">
                    <radus>1</radus>
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 5, 12,
                "unknown element <radus> in a Sphere (did you mean <radius>?); expected one of center, radius, rotate, scale, shader, translate");
    }

    @Test
    public void unknownElementFarFromAnyNameListsTheExpectedOnes() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <sphere/>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 4, 12, "unknown element <sphere> in <scene>;"
                + " expected one of backColor, camera, exposure, image, light, samples, shader, surface, texture");
    }

    @Test
    public void propertyOfTheOtherCameraTypeIsUnknown() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="OrthographicCamera">
                    <projDistance>2</projDistance>
                  </camera>
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 3, 19, "unknown element <projDistance> in an OrthographicCamera;"
                + " expected one of viewDir, viewHeight, viewPoint, viewUp, viewWidth");
    }

    @Test
    public void misspelledTypeSuggestsTheClosestOne() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Sphre">
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 4, 25,
                "unknown type \"Sphre\" for <surface> (did you mean \"Sphere\"?); expected one of " + SURFACE_TYPES);
    }

    @Test
    public void wronglyCasedTypeSuggestsTheRightCase() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <shader name="a" type="lambertian"/>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 4, 39,
                "unknown type \"lambertian\" for <shader> (did you mean \"Lambertian\"?); expected one of " + SHADER_TYPES);
    }

    @Test
    public void typeOfTheWrongKindIsUnknownForThatElement() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="Sphere"/>
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 2, 26,
                "unknown type \"Sphere\" for <camera>; expected one of PerspectiveCamera, OrthographicCamera");
    }

    @Test
    public void typeWithoutAConstructorWithoutArgumentsCannotBeMade() {
        // Transformed is a Surface, but only a Group makes one (around itself).
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Transformed"/>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 4, 32, "type \"Transformed\" cannot be made from a scene file (it has no"
                + " public constructor without arguments); expected one of " + SURFACE_TYPES);
    }

    @Test
    public void surfaceWithoutTypeListsTheTypes() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface>
                    <radius>1</radius>
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 4, 12, "<surface> needs a type attribute; expected one of " + SURFACE_TYPES);
    }

    @Test
    public void shaderNameWrittenAsTextPointsToRef() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <shader name="blue" type="Lambertian"/>
                  <surface type="Sphere">
                    <shader>blue</shader>
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 6, 13, "<shader> needs a type attribute; expected one of " + SHADER_TYPES
                + " (to reuse a named object, write <shader ref=\"blue\"/>)");
    }

    @Test
    public void unknownAttributeOnAnObjectElement() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Sphere" color="red">
                  </surface>
                </scene>
                """);
        // "  <surface type=\"Sphere\" color=\"red\">" is 37 characters.
        SceneFixtures.assertError(e, bad(), 4, 38, "unknown attribute color on <surface>; expected type, name or ref");
    }

    @Test
    public void unknownAttributeOnAValueElement() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image units="px">4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 3, 21, "unknown attribute units on <image>; expected no attributes");
    }

    @Test
    public void unknownAttributeOnTheScene() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene version="2">
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 1, 20, "unknown attribute version on <scene>; expected no attributes");
    }

    @Test
    public void refToANameDefinedLaterSaysWhereItIs() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Sphere">
                    <shader ref="late"/>
                  </surface>
                  <shader name="late" type="Lambertian"/>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 5, 25,
                "ref \"late\" names an object defined later, on line 7; expected the name of an object defined before it");
    }

    @Test
    public void refToTheObjectItIsInsideSaysSo() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Group" name="outer">
                    <surface ref="outer"/>
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 5, 27,
                "ref \"outer\" names the object it is inside (line 4); expected the name of an object defined before it");
    }

    @Test
    public void refToAnObjectOfTheWrongKind() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <shader name="blue" type="Lambertian"/>
                  <surface ref="blue"/>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 5, 24, "ref \"blue\" names a Lambertian; expected a Surface");
    }

    @Test
    public void refWithItsOwnPropertiesIsRefused() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <shader name="blue" type="Lambertian"/>
                  <surface type="Sphere">
                    <shader ref="blue">
                      <diffuseColor>1 0 0</diffuseColor>
                    </shader>
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 6, 24,
                "<shader ref=\"blue\"> also has properties; expected the ref alone (it reuses the named object as it is)");
    }

    @Test
    public void refWithATypeAndANameIsRefused() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <shader name="blue" type="Lambertian"/>
                  <shader ref="blue" type="Phong" name="shiny"/>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 5, 49,
                "<shader ref=\"blue\"> also has a type and a name; expected the ref alone (it reuses the named object as it is)");
    }

    @Test
    public void duplicateNameIsReportedAtItsSecondDefinition() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <shader name="blue" type="Lambertian"/>
                  <shader name="blue" type="Phong"/>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 5, 37,
                "duplicate name \"blue\" (first given on line 4); expected each name to be used once");
    }

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
                + "; expected an OBJ file (a relative path in <data> starts from the scene file's folder)");
    }

    @Test
    public void errorInAMeshFileNamesTheObjFileAndItsLine() {
        Path obj = SceneFixtures.write(folder, "meshes/broken.obj", """
                v 0 0 0
                v 1 0 0
                f 1 2 3
                """);
        Path scene = SceneFixtures.write(folder, "mesh.xml", """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Mesh">
                    <data>meshes/broken.obj</data>
                  </surface>
                </scene>
                """);
        SceneException e = SceneFixtures.loadError(scene);
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

    private Path bad() {
        return folder.getRoot().toPath().resolve("bad.xml");
    }
}
