package ray.scene;

import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * Checks that an element left open is reported where its start tag begins (its '<'), with the place
 * where the parser noticed (an end tag of an element around it, or the end of the file) in the
 * problem. An end tag that closes nothing open is a misspelling, reported where it is
 * ({@link SceneLoaderErrorsTest}, "mismatched end tag is malformed XML at that tag").
 */
public class SceneLoaderUnclosedTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void missingEndTagIsReportedAtTheStartTag() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera">
                    <viewPoint>0 0 5</viewPoint>
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 2, 3,
                "malformed XML: <camera> is never closed (found </scene> at 5:1); expected </camera> before it");
    }

    @Test
    public void startTagOverSeveralLinesIsReportedAtItsFirstLine() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Sphere">
                    <shader
                        type="Lambertian">
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 5, 5,
                "malformed XML: <shader> is never closed (found </surface> at 7:3); expected </shader> before it");
    }

    @Test
    public void ofSeveralElementsLeftOpenTheInnermostIsReported() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Group">
                    <surface type="Sphere">
                </scene>
                """);
        SceneFixtures.assertError(e, bad(), 5, 5,
                "malformed XML: <surface> is never closed (found </scene> at 6:1); expected </surface> before it");
    }

    @Test
    public void elementOpenAtTheEndOfTheFileIsReportedAtItsStartTag() {
        SceneException e = SceneFixtures.loadError(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Sphere">
                    <radius>1</radius>
                """);
        SceneFixtures.assertError(e, bad(), 4, 3,
                "malformed XML: <surface> is never closed (the file ends at 6:1); expected </surface> before the end of the file");
    }

    @Test
    public void byteOrderMarkTabsAndCarriageReturnsDoNotShiftThePlace() {
        SceneException e = SceneFixtures.loadError(folder, "\uFEFF<scene>\r\n\t<camera type=\"PerspectiveCamera\">\r\n</scene>\r\n");
        SceneFixtures.assertError(e, bad(), 2, 2,
                "malformed XML: <camera> is never closed (found </scene> at 3:1); expected </camera> before it");
    }

    private Path bad() {
        return folder.getRoot().toPath().resolve("bad.xml");
    }
}
