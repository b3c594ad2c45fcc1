package ray.scene;

import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * Checks errors in values: the wrong number of values, words and special values where numbers
 * belong, fractions where integers belong, values out of range (radius, image size, samples,
 * exposure, view size, projection distance, camera axes, scale), a mesh without its file, and a
 * scene without a camera or an image size. Each error is checked whole: the file, line and column,
 * what is wrong and what was expected. (Box corners in either order load, with a warning:
 * SceneLoaderWarningsTest.)
 *
 * <p>SAX locates an element where its start tag ends, so an element's column is the one just after
 * its {@code >} (for {@code "    <radius>"}, column 13); each element sits on its own line.
 */
public class SceneLoaderValueErrorsTest {
    private static final String THREE_CENTER_NUMBERS = "three numbers, e.g. <center>1 0 -2.5</center>";

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void vectorWithTwoValuesAsksForThree() {
        SceneException e = loadSphereError("    <center>1 2</center>\n");
        SceneFixtures.assertError(e, bad(), 5, 13, "<center> has 2 values; expected " + THREE_CENTER_NUMBERS);
    }

    @Test
    public void vectorWithFourValuesAsksForThree() {
        SceneException e = loadSphereError("    <center>1 2 3 4</center>\n");
        SceneFixtures.assertError(e, bad(), 5, 13, "<center> has 4 values; expected " + THREE_CENTER_NUMBERS);
    }

    @Test
    public void emptyNumberAsksForOne() {
        SceneException e = loadSphereError("    <radius> </radius>\n");
        SceneFixtures.assertError(e, bad(), 5, 13, "<radius> has no value; expected a number");
    }

    @Test
    public void imageWithOneValueAsksForTwoIntegers() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>300</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 3, 10, "<image> has 1 value; expected two integers");
    }

    @Test
    public void wordsAndSpecialValuesAreNotNumbers() {
        // Java's own parser would take NaN, Infinity, hex floats and a "d" suffix; a scene takes plain decimals.
        for (String word : new String[] {"abc", "NaN", "Infinity", "-Infinity", "0x10", "1d", "1,5"}) {
            SceneException e = loadSphereError("    <radius>" + word + "</radius>\n");
            SceneFixtures.assertError(e, bad(), 5, 13, "\"" + word + "\" in <radius> is not a number; expected a number");
        }
    }

    @Test
    public void specialValuesInAVectorAreNotNumbers() {
        for (String word : new String[] {"NaN", "Infinity", "-Infinity", "inf"}) {
            SceneException e = loadSphereError("    <center>0 " + word + " 0</center>\n");
            SceneFixtures.assertError(e, bad(), 5, 13,
                    "\"" + word + "\" in <center> is not a number; expected " + THREE_CENTER_NUMBERS);
        }
    }

    @Test
    public void numberBeyondDoubleRangeIsTooLarge() {
        SceneException e = loadSphereError("    <center>0 1e999 0</center>\n");
        SceneFixtures.assertError(e, bad(), 5, 13, "\"1e999\" in <center> is too large; expected " + THREE_CENTER_NUMBERS);
    }

    @Test
    public void fractionalImageSizeIsNotAnInteger() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>300.5 200</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 3, 10, "\"300.5\" in <image> is not an integer; expected two integers");
    }

    @Test
    public void imageSizeBeyondIntIsTooLarge() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>300 99999999999</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 3, 10, "\"99999999999\" in <image> is too large; expected two integers");
    }

    @Test
    public void fractionalSamplesIsNotAnInteger() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <samples>2.5</samples>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 4, 12, "\"2.5\" in <samples> is not an integer; expected an integer");
    }

    @Test
    public void negativeAndZeroRadiusAreInvalid() {
        SceneException negative = loadSphereError("    <radius>-1</radius>\n");
        SceneFixtures.assertError(negative, bad(), 5, 13, "radius is -1.0; expected a positive number");
        SceneException zero = loadSphereError("    <radius>0</radius>\n");
        SceneFixtures.assertError(zero, bad(), 5, 13, "radius is 0.0; expected a positive number");
    }

    @Test
    public void zeroImageSizeIsInvalid() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>0 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 3, 10, "image size is 0 3; expected two positive integers");
    }

    @Test
    public void negativeImageSizeIsInvalid() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>-4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 3, 10, "image size is -4 3; expected two positive integers");
    }

    @Test
    public void zeroSamplesIsInvalid() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <samples>0</samples>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 4, 12, "samples is 0; expected a positive integer");
    }

    @Test
    public void negativeSamplesIsInvalid() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <samples>-2</samples>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 4, 12, "samples is -2; expected a positive integer");
    }

    @Test
    public void negativeExposureIsInvalid() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <exposure>-0.5</exposure>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 4, 13, "exposure is -0.5; expected a number ≥ 0");
    }

    @Test
    public void zeroViewWidthIsInvalid() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera">
                    <viewWidth>0</viewWidth>
                  </camera>
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 3, 16, "viewWidth is 0.0; expected a positive number");
    }

    @Test
    public void zeroViewHeightIsInvalid() {
        SceneException e = loadError("""
                <scene>
                  <camera type="OrthographicCamera">
                    <viewHeight>0</viewHeight>
                  </camera>
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 3, 17, "viewHeight is 0.0; expected a positive number");
    }

    @Test
    public void zeroAndNegativeProjDistanceAreInvalid() {
        for (String distance : new String[] {"0", "-1.5"}) {
            SceneException e = loadError("""
                    <scene>
                      <camera type="PerspectiveCamera">
                        <projDistance>%s</projDistance>
                      </camera>
                      <image>4 3</image>
                    </scene>
                    """.formatted(distance));
            SceneFixtures.assertError(e, bad(), 3, 19,
                    "projDistance is " + Double.parseDouble(distance) + "; expected a positive number");
        }
    }

    @Test
    public void zeroViewDirIsReportedAtItsCamera() {
        // The axes are checked once the whole camera is read, so the error points at <camera>.
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera">
                    <viewDir>0 0 0</viewDir>
                  </camera>
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 2, 36,
                "invalid PerspectiveCamera: viewDir is (0.0, 0.0, 0.0); expected a nonzero vector");
    }

    @Test
    public void viewUpParallelToViewDirIsReportedAtItsCamera() {
        SceneException e = loadError("""
                <scene>
                  <camera type="OrthographicCamera">
                    <viewDir>0 0 -1</viewDir>
                    <viewUp>0 0 2</viewUp>
                  </camera>
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 2, 37, "invalid OrthographicCamera: viewUp (0.0, 0.0, 2.0) is parallel to"
                + " viewDir (0.0, 0.0, -1.0); expected a viewUp that is not parallel to viewDir");
    }

    @Test
    public void zeroViewUpIsReportedAtItsCamera() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera">
                    <viewUp>0 0 0</viewUp>
                  </camera>
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 2, 36,
                "invalid PerspectiveCamera: viewUp is (0.0, 0.0, 0.0); expected a nonzero vector not parallel to viewDir");
    }

    @Test
    public void zeroScaleIsRefused() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Group">
                    <scale>1 0 1</scale>
                    <surface type="Sphere"/>
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 4, 25,
                "invalid Group: scale (1.0, 0.0, 1.0) is zero on an axis; expected a nonzero scale on every axis");
    }

    /** Found by the fuzzer: no factor is zero, but their product overflows, so the transform has no inverse. */
    @Test
    public void scaleWhoseProductOverflowsIsRefused() {
        SceneFixtures.write(folder, "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Mesh">
                    <data>m.obj</data>
                    <scale>5 5 1.7976931348623157e308</scale>
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 4, 24, "invalid Mesh: the transform cannot be inverted (its determinant is"
                + " Infinity); expected scales and rotations whose product is nonzero and finite");
    }

    @Test
    public void emptyMeshPathAsksForAFile() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Mesh">
                    <data> </data>
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 5, 11, "<data> is empty; expected a file path");
    }

    @Test
    public void meshWithoutDataAsksForIt() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Mesh">
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 4, 24,
                "invalid Mesh: no <data> is given; expected <data> with the path of an OBJ file");
    }

    @Test
    public void sceneWithoutCameraIsReportedAtTheSceneElement() {
        SceneException e = loadError("""
                <?xml version="1.0"?>
                <scene>
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 2, 8,
                "the scene has no <camera>; expected a camera, e.g. <camera type=\"PerspectiveCamera\"/>");
    }

    @Test
    public void sceneWithoutImageIsReportedAtTheSceneElement() {
        SceneException e = loadError("""
                <scene>
                  <camera type="PerspectiveCamera"/>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 1, 8, "the scene has no <image> size; expected <image>width height</image>");
    }

    /** The error of a scene whose line 5 is {@code line}, inside a sphere that starts on line 4. */
    private SceneException loadSphereError(String line) {
        return loadError("<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE + "  <surface type=\"Sphere\">\n" + line + "  </surface>\n</scene>\n");
    }

    private SceneException loadError(String xml) {
        return SceneFixtures.loadError(folder, xml);
    }

    private Path bad() {
        return folder.getRoot().toPath().resolve("bad.xml");
    }
}
