package ray.scene;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.surface.Cylinder;
import ray.surface.Surface;

/**
 * Checks {@code <surface type="Cylinder">}: its three properties and their defaults, and the located
 * errors for a size that is not positive. (Whether it is hit is the student's extra credit, tested
 * by CylinderTest, so nothing here traces a ray.)
 */
public class SceneLoaderCylinderTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private Cylinder onlyCylinder(String body) {
        Scene scene = SceneFixtures.loadBody(folder, body);
        Surface only = scene.getSurfaces().children().get(0);
        assertTrue("the scene's one surface must load as a Cylinder, not " + only, only instanceof Cylinder);
        return (Cylinder) only;
    }

    @Test
    public void centerRadiusAndHeightAreRead() {
        Cylinder cylinder = onlyCylinder("""
                  <surface type="Cylinder">
                    <center>1 -2 0.5</center>
                    <radius>0.25</radius>
                    <height>3</height>
                  </surface>
                """);
        assertVec("center (of the bottom cap)", v(1, -2, 0.5), cylinder.getCenter(), 0);
        assertEquals("radius", 0.25, cylinder.getRadius(), 0);
        assertEquals("height", 3, cylinder.getHeight(), 0);
        assertEquals("Cylinder[center (1.0, -2.0, 0.5), radius 0.25, height 3.0]", cylinder.toString());
    }

    @Test
    public void omittedPropertiesTakeTheDocumentedDefaults() {
        Cylinder cylinder = onlyCylinder("  <surface type=\"Cylinder\"/>\n");
        assertVec("default center", v(0, 0, 0), cylinder.getCenter(), 0);
        assertEquals("default radius", 1, cylinder.getRadius(), 0);
        assertEquals("default height", 1, cylinder.getHeight(), 0);
    }

    @Test
    public void aHeightOrRadiusThatIsNotPositiveIsALocatedError() {
        Path bad = folder.getRoot().toPath().resolve("bad.xml");
        SceneException flat = SceneFixtures.loadError(folder,
                "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE + "  <surface type=\"Cylinder\">\n    <height>0</height>\n  </surface>\n</scene>\n");
        SceneFixtures.assertError(flat, bad, 5, 13, "height is 0.0; expected a positive number");
        SceneException negative = SceneFixtures.loadError(folder,
                "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE + "  <surface type=\"Cylinder\">\n    <radius>-2</radius>\n  </surface>\n</scene>\n");
        SceneFixtures.assertError(negative, bad, 5, 13, "radius is -2.0; expected a positive number");
    }
}
