package ray.render;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertThrows;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.Test;
import ray.image.ImageDiff;
import ray.image.PngWriter;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.scene.SceneException;
import ray.scene.SceneFiles;
import ray.scene.SceneLoader;
import ray.scene.SceneOptions;
import ray.shading.Course;

/**
 * ray1's scenes in the course's 2019 conventions (scenes-2019/) render by those conventions like
 * their references, a pixel of the plainest one has the value worked out in its file, and the
 * effects each scene calls for are the ones the render pays for.
 */
public class Course2019ScenesTest {
    private static final Path SCENES = Path.of("scenes-2019");

    private static RenderResult render(String name, Course course) {
        Scene scene = SceneLoader.load(SCENES.resolve(name + ".xml"), SceneOptions.of(course, null));
        return new Renderer(scene, 0, 0).render();
    }

    @Test
    public void everySceneRendersLikeItsReference() throws IOException {
        List<Path> files = SceneFiles.under(SCENES, SCENES.resolve("reference"));
        assertTrue("the 2019 scenes: " + files, files.size() >= 5);
        for (Path file : files) {
            Scene scene = SceneLoader.load(file, SceneOptions.of(Course.Y2019, null));
            assertEquals(file + " loads without warnings", List.of(), scene.warnings());
            BufferedImage rendered = PngWriter.toBufferedImage(new Renderer(scene, 0, 0).render().image, scene.getExposure());
            BufferedImage reference = ImageIO.read(SCENES.resolve("reference/" + SceneFiles.nameOf(file) + ".png").toFile());
            ImageDiff.Result diff = ImageDiff.compare(reference, rendered);
            assertTrue(file + ": " + diff, diff.passed());
        }
    }

    @Test
    public void theLambertianSpheresCenterIsRhoOverPiTimesIrradiance() {
        // The center pixel's ray meets the sphere head on at (0, 0, 1): n·l = 1, r = 4, I = 64.
        Vec3 center = render("one-sphere-lambertian", Course.Y2019).image.get(100, 100);
        assertVec(v(0.8, 0.5, 0.2).times(64 / 16.0 / Math.PI), center, 1e-12);
    }

    @Test
    public void the2017RulesMakeTheSameSpherePiTimesBrighter() throws IOException {
        Path file = SCENES.resolve("one-sphere-lambertian.xml");
        Vec3 y2017 = new Renderer(SceneLoader.load(file, SceneOptions.of(Course.Y2017, null)), 0, 0).render().image.get(100, 100);
        assertVec(v(0.8, 0.5, 0.2).times(4), y2017, 1e-12);
    }

    @Test
    public void aMirrorSceneUnder2017IsRefused() {
        SceneException e = assertThrows(SceneException.class,
                () -> SceneLoader.load(SCENES.resolve("mirror-spheres.xml"), SceneOptions.of(Course.Y2017, null)));
        assertTrue(e.getMessage(), e.getMessage().contains("<mirrorCoefficient> (lines ")
                && e.getMessage().endsWith("render it with --course 2019 (or set course = 2019 in assignment.properties)"));
    }

    @Test
    public void onlyMirrorScenesTraceMirrorRays() {
        for (String name : List.of("one-sphere-lambertian", "three-spheres-phong", "textured-globe")) {
            RenderResult r = render(name, Course.Y2019);
            assertEquals(name, 0, r.rays.reflection);
            assertTrue(name + " " + r.plan, !r.plan.toString().contains("reflection("));
        }
        RenderResult mirrors = render("mirror-spheres", Course.Y2019);
        assertTrue("mirror rays: " + mirrors.rays.reflection, mirrors.rays.reflection > 1000);
        // Only the two mirror spheres trace them: at most one per camera ray that meets one, plus the
        // bounces, each bounded by the 12 hits of a path.
        assertTrue(mirrors.rays.reflection < 11 * mirrors.rays.camera);
    }
}
