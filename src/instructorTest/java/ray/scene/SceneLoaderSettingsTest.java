package ray.scene;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.shading.Light;

/**
 * Checks the scene-wide elements ({@code <image>}, {@code <exposure>}, {@code <backColor>},
 * {@code <samples>}, {@code <light>}), their defaults, the scene's name, and what the format
 * forgives: element names in any case, white space around numbers, comments, the XML header.
 */
public class SceneLoaderSettingsTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void settingsAreRead() {
        Scene scene = SceneFixtures.loadText(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>300 200</image>
                  <exposure>2.5</exposure>
                  <backColor>0.1 0.2 0.3</backColor>
                  <samples>16</samples>
                </scene>
                """);
        assertEquals(300, scene.getWidth());
        assertEquals(200, scene.getHeight());
        assertEquals(2.5, scene.getExposure(), 0);
        assertVec(v(0.1, 0.2, 0.3), scene.getBackColor(), 0);
        assertEquals(16, scene.getSamples());
    }

    @Test
    public void omittedSettingsTakeTheDesignDefaults() {
        Scene scene = SceneFixtures.loadBody(folder, "");
        assertEquals(1.0, scene.getExposure(), 0);
        assertVec(v(0, 0, 0), scene.getBackColor(), 0);
        assertEquals(1, scene.getSamples());
        assertTrue(scene.getLights().isEmpty());
        assertTrue(scene.getSurfaces().children().isEmpty());
    }

    @Test
    public void lightsKeepTheirOrderPositionAndIntensity() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <light>
                    <position>3 4 5</position>
                    <intensity>40 30 20</intensity>
                  </light>
                  <light>
                    <position>-1 0 2.5</position>
                    <intensity>0.5 0.5 0.5</intensity>
                  </light>
                """);
        assertEquals(2, scene.getLights().size());
        Light first = scene.getLights().get(0);
        Light second = scene.getLights().get(1);
        assertVec(v(3, 4, 5), first.getPosition(), 0);
        assertVec(v(40, 30, 20), first.getIntensity(), 0);
        assertVec(v(-1, 0, 2.5), second.getPosition(), 0);
        assertVec(v(0.5, 0.5, 0.5), second.getIntensity(), 0);
    }

    @Test
    public void lightWithoutPropertiesSitsAtTheOriginWithUnitIntensity() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <light/>
                  <light>
                    <position>1 2 3</position>
                  </light>
                """);
        assertVec(v(0, 0, 0), scene.getLights().get(0).getPosition(), 0);
        assertVec(v(1, 1, 1), scene.getLights().get(0).getIntensity(), 0);
        assertVec(v(1, 2, 3), scene.getLights().get(1).getPosition(), 0);
        assertVec(v(1, 1, 1), scene.getLights().get(1).getIntensity(), 0);
    }

    @Test
    public void sceneNameIsTheFileNameWithoutXml() {
        Path file = SceneFixtures.write(folder, "rooms/my-room.xml", "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE + "</scene>\n");
        assertEquals("my-room", SceneLoader.load(file).getName());
    }

    @Test
    public void sceneNameKeepsAnExtensionOtherThanXml() {
        Path file = SceneFixtures.write(folder, "room.scene", "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE + "</scene>\n");
        assertEquals("room.scene", SceneLoader.load(file).getName());
    }

    @Test
    public void elementNamesMatchIgnoringCase() {
        Scene scene = SceneFixtures.loadText(folder, """
                <SCENE>
                  <Camera type="OrthographicCamera">
                    <VIEWPOINT>1 2 3</VIEWPOINT>
                  </Camera>
                  <IMAGE>8 6</IMAGE>
                  <BackColor>0 0.5 1</BackColor>
                  <exPOSURE>2</exPOSURE>
                  <LIGHT>
                    <Position>7 8 9</Position>
                  </LIGHT>
                </SCENE>
                """);
        assertEquals(8, scene.getWidth());
        assertVec(v(0, 0.5, 1), scene.getBackColor(), 0);
        assertEquals(2.0, scene.getExposure(), 0);
        assertVec(v(7, 8, 9), scene.getLights().get(0).getPosition(), 0);
        // The other camera properties are protected: the instructor's SceneLoaderCameraTest checks them,
        // in any case, through the rays the camera makes.
        assertVec(v(1, 2, 3), scene.getCamera().getViewPoint(), 0);
    }

    @Test
    public void numbersMayBeSurroundedByWhiteSpaceNewlinesAndTabs() {
        Scene scene = SceneFixtures.loadText(folder, "<scene>\n"
                + "  <camera type=\"PerspectiveCamera\"/>\n"
                + "  <image>\n\t300\t\n  200  \n</image>\n"
                + "  <exposure> \t2 \n</exposure>\n"
                + "  <backColor>\t0.5\n 0.25\t\t1 </backColor>\n"
                + "  <samples>\n4\n</samples>\n"
                + "</scene>\n");
        assertEquals(300, scene.getWidth());
        assertEquals(200, scene.getHeight());
        assertEquals(2.0, scene.getExposure(), 0);
        assertVec(v(0.5, 0.25, 1), scene.getBackColor(), 0);
        assertEquals(4, scene.getSamples());
    }

    @Test
    public void numbersMayHaveSignsExponentsAndBareDecimalPoints() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <backColor>+1 .5 5.</backColor>
                  <light>
                    <position>-0.5E+1 1e-1 -.25</position>
                  </light>
                """);
        assertVec(v(1, 0.5, 5), scene.getBackColor(), 0);
        assertVec(v(-5, 0.1, -0.25), scene.getLights().get(0).getPosition(), 0);
    }

    @Test
    public void commentsAndTheXmlHeaderAreIgnored() {
        Scene scene = SceneFixtures.loadText(folder, """
                <?xml version="1.0" encoding="UTF-8"?>
                <!-- A scene with comments everywhere a comment may go. -->
                <scene>
                  <!-- the camera -->
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <exposure> <!-- brighter --> 2 </exposure>
                  <!--
                    <exposure>9</exposure>
                  -->
                </scene>
                <!-- trailing comment -->
                """);
        assertEquals(2.0, scene.getExposure(), 0);
    }

    @Test
    public void windowsLineEndingsAreAccepted() {
        Scene scene = SceneFixtures.loadText(folder, "<scene>\r\n  <camera type=\"PerspectiveCamera\"/>\r\n"
                + "  <image>4\r\n3</image>\r\n</scene>\r\n");
        assertEquals(4, scene.getWidth());
        assertEquals(3, scene.getHeight());
    }
}
