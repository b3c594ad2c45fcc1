package ray.scene;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertThrows;

import java.nio.file.Path;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.surface.Box;

/**
 * Checks the loader's warnings: a scene that loads and renders, but has something worth a remark,
 * keeps one line per remark, {@code FILE:LINE:COL: warning: what}, located where an error in the
 * same element would be. The boxes here are given with minPt above maxPt on some axis, or equal to
 * it: they are built from the corners as given, as the course's renderer builds them.
 *
 * <p>SAX locates an element where its start tag ends: {@code "  <surface type="Box">"} is at column 23.
 */
public class SceneLoaderWarningsTest {
    private static final String AS_GIVEN = "; built from the corners as given, as the course's renderer does";

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    /** A scene with a camera and an image size (lines 2 and 3), then one box per pair of corners, each on four lines from line 4. */
    private Path boxes(String... corners) {
        StringBuilder xml = new StringBuilder("<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE);
        for (int i = 0; i < corners.length; i += 2) {
            xml.append("  <surface type=\"Box\">\n")
                    .append("    <minPt>").append(corners[i]).append("</minPt>\n")
                    .append("    <maxPt>").append(corners[i + 1]).append("</maxPt>\n")
                    .append("  </surface>\n");
        }
        return SceneFixtures.write(folder, "boxes.xml", xml.append("</scene>\n").toString());
    }

    @Test
    public void boxInvertedInOneAxisLoadsWithAWarningAtItsSurface() {
        // The course's own wall: minPt.y = 6 above maxPt.y = −3.
        Path file = boxes("3.0 6.0 -12.0", "3.1 -3.0 3.0");
        Scene scene = SceneLoader.load(file);
        assertEquals(List.of(file + ":4:23: warning: Box minPt.y > maxPt.y" + AS_GIVEN), scene.warnings());
        Box box = (Box) scene.getSurfaces().children().get(0);
        assertEquals(12, box.triangleCount());
    }

    @Test
    public void boxInvertedInTwoAxesIsOneWarningNamingBoth() {
        Path file = boxes("2 2 0", "1 1 1");
        assertEquals(List.of(file + ":4:23: warning: Box minPt.x > maxPt.x and minPt.y > maxPt.y" + AS_GIVEN),
                SceneLoader.load(file).warnings());
    }

    @Test
    public void flatBoxLoadsWithAWarning() {
        Path file = boxes("-1 0.5 -3", "1 0.5 3");
        Scene scene = SceneLoader.load(file);
        assertEquals(List.of(file + ":4:23: warning: Box minPt.y = maxPt.y (a flat box)" + AS_GIVEN), scene.warnings());
        assertEquals(2, ((Box) scene.getSurfaces().children().get(0)).triangleCount());
    }

    @Test
    public void segmentBoxLoadsWithAWarningAndNoTriangles() {
        Path file = boxes("0 0 0", "0 0 1");
        Scene scene = SceneLoader.load(file);
        assertEquals(List.of(file + ":4:23: warning: Box minPt.x = maxPt.x and minPt.y = maxPt.y (a line segment, which no ray"
                + " hits); it has no faces to draw"), scene.warnings());
        assertEquals(0, ((Box) scene.getSurfaces().children().get(0)).triangleCount());
    }

    @Test
    public void eachBoxWarnsAtItsOwnLineInFileOrderAndOrdinaryBoxesDoNot() {
        Path file = boxes("0 0 0", "1 1 1", "0 2 0", "1 1 1", "-1 -1 -1", "1 1 1", "0 0 5", "1 1 1");
        assertEquals(List.of(file + ":8:23: warning: Box minPt.y > maxPt.y" + AS_GIVEN,
                file + ":16:23: warning: Box minPt.z > maxPt.z" + AS_GIVEN), SceneLoader.load(file).warnings());
        assertEquals(List.of(), SceneLoader.load(boxes("0 0 0", "1 1 1")).warnings());
    }

    @Test
    public void boxInsideAGroupWarnsAtItsOwnElement() {
        Path file = SceneFixtures.write(folder, "group.xml", """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Group">
                    <translate>0 1 0</translate>
                    <surface type="Box">
                      <minPt>0 0 2</minPt>
                      <maxPt>1 1 1</maxPt>
                    </surface>
                  </surface>
                </scene>
                """);
        assertEquals(List.of(file + ":6:25: warning: Box minPt.z > maxPt.z" + AS_GIVEN), SceneLoader.load(file).warnings());
    }

    @Test
    public void warningsAreReadOnlyAndCarriedIntoTheCameraFrame() {
        Path file = boxes("0 2 0", "1 1 1");
        Scene scene = SceneLoader.load(file);
        assertThrows(UnsupportedOperationException.class, () -> scene.warnings().add("more"));
        assertEquals(scene.warnings(), scene.inCameraFrame().warnings());
    }
}
