package ray.numerics;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import ray.accuracy.SceneCopy;
import ray.image.PngWriter;
import ray.math.Vec3;
import ray.render.RenderPlan;
import ray.render.Renderer;
import ray.scene.CameraFrame;
import ray.scene.Scene;
import ray.scene.SceneLoader;
import ray.surface.Surface;

/**
 * Shipped scenes placed far from the origin as a scene file written there would hold them: every
 * position p (spheres' centers, vertices, box corners, lights, the eye) becomes p + T in its own
 * numbers, rounded once to the doubles near T, with no transform in between (unlike
 * {@link MovedScenes}, which places the scene through a group). Rendered from the camera's frame,
 * as every render is, or in the scene's own coordinates, as renderers did before, for comparison.
 */
final class FarScenes {
    private FarScenes() {
    }

    /** scenes/NAME.xml moved by {@code translate}, its image {@code shrink} times smaller on each side. */
    static Scene load(String name, Vec3 translate, int shrink) {
        Scene original = SceneLoader.load(Path.of("scenes", name + ".xml"));
        Scene moved = CameraFrame.seenFrom(original, translate.negate());
        moved.setImage(original.getWidth() / shrink, original.getHeight() / shrink);
        return moved;
    }

    /** The render from the camera's frame (what ray1 does), as 8-bit pixels. */
    static BufferedImage render(Scene scene) {
        return PngWriter.toBufferedImage(new Renderer(RenderPlan.of(scene), 0).render().image, scene.getExposure());
    }

    /**
     * The render with textbook intersection (the quadratic sphere, Cramer's-rule triangles, boxes'
     * and meshes' too), from the camera's frame ({@code world} false: the textbook surfaces made from
     * the moved scene's own numbers) or in the scene's own coordinates.
     */
    static BufferedImage renderTextbook(Scene scene, boolean world) {
        Scene base = world ? scene : scene.inCameraFrame();
        Surface textbook = TextbookSurfaces.withTriangles(TextbookSurfaces.withTextbookSpheres(base.getSurfaces()), TextbookTriangles.CRAMER);
        Scene copy = SceneCopy.withSurfaces(base, textbook);
        copy.complete();
        RenderPlan plan = world ? RenderPlan.of(copy).withWorldFrame() : RenderPlan.of(copy);
        return PngWriter.toBufferedImage(new Renderer(plan, 0).render().image, scene.getExposure());
    }

    /** The render in the scene's own coordinates (what ray1 did before the camera's frame), as 8-bit pixels. */
    static BufferedImage renderInWorldFrame(Scene scene) {
        return PngWriter.toBufferedImage(new Renderer(RenderPlan.of(scene).withWorldFrame(), 0).render().image, scene.getExposure());
    }
}
