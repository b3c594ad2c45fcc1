package ray.scene;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertThrows;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.nio.file.Path;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.shading.Course;
import ray.shading.Lambertian;
import ray.shading.ReflectionShader;
import ray.shading.Shader;
import ray.surface.Surface;

/**
 * Loading by a course's conventions: 2019's elements are refused under 2017 in one line naming them
 * all, a Lambertian or Phong becomes 2019's reflection shader (with 2019's defaults), and data paths
 * are found from the folders above the scene, as the course's scenes in sub-folders name them.
 */
public class SceneLoaderCourseTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private static final String MIRRORS = "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE
            + "  <shader type=\"Lambertian\" name=\"a\">\n"
            + "    <mirrorCoefficient>0.5 0.5 0.5</mirrorCoefficient>\n"
            + "  </shader>\n"
            + "  <shader type=\"Phong\" name=\"b\"><mirrorcoefficient>0.1 0.2 0.3</mirrorcoefficient></shader>\n"
            + "  <surface type=\"Sphere\"><shader ref=\"a\"/></surface>\n"
            + "  <surface type=\"Sphere\"><shader ref=\"a\"/><center>3 0 0</center></surface>\n"
            + "</scene>\n";

    private static SceneOptions options(Course course) {
        return SceneOptions.of(course, null);
    }

    @Test
    public void underTheOtherCourseEvery2019ElementIsNamedInOneLine() {
        Path file = SceneFixtures.write(folder, "mirrors.xml", MIRRORS);
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load(file, options(Course.Y2017)));
        assertEquals(file + ":5:24: <mirrorCoefficient> (line 5) and <mirrorcoefficient> (line 7) are in the course's 2019"
                + " conventions only, and this scene loads by 2017's; render it with --course 2019 (or set course = 2019"
                + " in assignment.properties)", e.getMessage());
    }

    @Test
    public void under2019ALambertianIsTheReflectionShaderAndANameIsOneObject() {
        Scene scene = SceneLoader.load(SceneFixtures.write(folder, "mirrors.xml", MIRRORS), options(Course.Y2019));
        List<Surface> spheres = scene.getSurfaces().children();
        Shader first = spheres.get(0).getShader();
        assertTrue(first.getClass().getName(), first instanceof ReflectionShader);
        assertSame(first, spheres.get(1).getShader());
        assertVec(v(0.5, 0.5, 0.5), ((ReflectionShader) first).getMirrorCoefficient(), 0);
        assertEquals(Course.Y2019, first.course());
        assertEquals("Lambertian", first.toString());
    }

    @Test
    public void aLambertianWithoutColorIs02GrayIn2019AndWhiteIn2017() {
        String xml = "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE + "  <surface type=\"Sphere\"><shader type=\"Lambertian\"/></surface>\n</scene>\n";
        Path file = SceneFixtures.write(folder, "gray.xml", xml);
        assertVec(v(0.2, 0.2, 0.2), SceneLoader.load(file, options(Course.Y2019)).getSurfaces().children().get(0).getShader()
                .getDiffuseColor(), 0);
        Shader y2017 = SceneLoader.load(file, options(Course.Y2017)).getSurfaces().children().get(0).getShader();
        assertTrue(y2017 instanceof Lambertian);
        assertVec(v(1, 1, 1), y2017.getDiffuseColor(), 0);
    }

    @Test
    public void aSurfaceWithoutAShaderAndAGlazesDefaultSubstrateAreShadedByTheCourse() {
        String xml = "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE + "  <surface type=\"Sphere\"/>\n"
                + "  <surface type=\"Sphere\"><shader type=\"Glazed\"/></surface>\n</scene>\n";
        Path file = SceneFixtures.write(folder, "plain.xml", xml);
        List<Surface> y2019 = SceneLoader.load(file, options(Course.Y2019)).getSurfaces().children();
        Shader plain = y2019.get(0).getShader();
        assertTrue(plain instanceof ReflectionShader);
        assertVec(v(1, 1, 1), plain.getDiffuseColor(), 0);
        assertEquals(Course.Y2019, ((ray.shading.Glazed) y2019.get(1).getShader()).getSubstrate().course());
        List<Surface> y2017 = SceneLoader.load(file, options(Course.Y2017)).getSurfaces().children();
        assertTrue(y2017.get(0).getShader() instanceof Lambertian);
        assertTrue(((ray.shading.Glazed) y2017.get(1).getShader()).getSubstrate() instanceof Lambertian);
    }

    @Test
    public void aMirrorCoefficientAboveOneIsRefusedWithItsLine() {
        Path file = SceneFixtures.write(folder, "bad.xml", "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE
                + "  <shader type=\"Lambertian\">\n    <mirrorCoefficient>0 2 0</mirrorCoefficient>\n  </shader>\n</scene>\n");
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load(file, options(Course.Y2019)));
        assertTrue(e.getMessage(), e.getMessage().startsWith(file + ":5:24: mirrorCoefficient is "));
        assertTrue(e.getMessage(), e.getMessage().endsWith("; expected three numbers from 0 to 1"));
    }

    private static final String TRIANGLE_OBJ = "v 0 0 -1\nv 1 0 -1\nv 0 1 -1\nf 1 2 3\n";

    private Path sceneInASubFolder() {
        SceneFixtures.write(folder, "course/meshes/tri.obj", TRIANGLE_OBJ);
        return SceneFixtures.write(folder, "course/mesh_scenes/tri.xml", "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE
                + "  <surface type=\"Mesh\">\n    <data>meshes/tri.obj</data>\n  </surface>\n</scene>\n");
    }

    @Test
    public void aDataPathNotBesideTheSceneIsFoundAboveItWithAWarning() {
        Path file = sceneInASubFolder();
        Scene scene = SceneLoader.load(file, options(Course.Y2017));
        Path root = folder.getRoot().toPath().resolve("course").toAbsolutePath();
        assertEquals(List.of(file + ":5:11: warning: meshes/tri.obj is not there from the scene's folder; using "
                + root.resolve("meshes/tri.obj") + ", from " + root + " (--scene-root DIR names the folder data paths start from)"),
                scene.warnings());
        assertEquals(1, scene.getSurfaces().children().size());
    }

    @Test
    public void aSceneRootIsWhereDataPathsStartWithoutAWarning() {
        Path file = sceneInASubFolder();
        Path root = folder.getRoot().toPath().resolve("course");
        assertEquals(List.of(), SceneLoader.load(file, SceneOptions.of(Course.Y2017, root)).warnings());
        Path elsewhere = folder.getRoot().toPath().resolve("course/mesh_scenes");
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load(file, SceneOptions.of(Course.Y2017, elsewhere)));
        assertEquals(file + ":5:11: no such mesh file " + elsewhere.toAbsolutePath().resolve("meshes/tri.obj")
                + "; expected an OBJ file (a relative path in <data> starts from the scene root " + elsewhere.toAbsolutePath()
                + " (--scene-root))", e.getMessage());
    }

    /**
     * Without a course asked for, a scene in one of ray1's scene folders loads by that folder's
     * conventions, whatever the assignment's: under scenes-2019/ the mirror scene is 2019's, under
     * scenes/ (even in a sub-folder) a plain Lambertian stays 2017's with a 2019 assignment; any other
     * folder follows the assignment (2017 by default), and an asked-for course always wins.
     */
    @Test
    public void aShippedScenesFolderDecidesItsCourse() {
        String plain = "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE + "  <surface type=\"Sphere\"><shader type=\"Lambertian\"/></surface>\n</scene>\n";
        Path mirrors = SceneFixtures.write(folder, "project/scenes-2019/mirrors.xml", MIRRORS);
        assertTrue(shaderOf(SceneLoader.load(mirrors)) instanceof ReflectionShader);
        Path shipped = SceneFixtures.write(folder, "project/scenes/hard/plain.xml", plain);
        Path elsewhere = SceneFixtures.write(folder, "mine/plain.xml", plain);
        ray.assignment.Assignment before = ray.assignment.Assignment.current();
        try {
            ray.assignment.Assignment.use(ray.assignment.Assignment.preset("course-2019"));
            assertTrue(shaderOf(SceneLoader.load(shipped)) instanceof Lambertian);
            assertTrue(shaderOf(SceneLoader.load(elsewhere)) instanceof ReflectionShader);
            assertTrue(shaderOf(SceneLoader.load(shipped, SceneOptions.of(Course.Y2019, null))) instanceof ReflectionShader);
        } finally {
            ray.assignment.Assignment.use(before);
        }
        assertTrue(shaderOf(SceneLoader.load(elsewhere)) instanceof Lambertian);
    }

    private static Shader shaderOf(ray.scene.Scene scene) {
        return scene.getSurfaces().children().get(0).getShader();
    }
}
