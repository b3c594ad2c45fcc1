package ray.accuracy;

import java.util.List;
import ray.scene.Scene;
import ray.surface.Surface;

/** Copies of a loaded scene that differ in one part, for rendering the same scene several ways. */
public final class SceneCopy {
    private SceneCopy() {
    }

    /** {@code scene} with {@code root} as its only surface; camera, image, lights, shaders, textures and settings shared. */
    public static Scene withSurfaces(Scene scene, Surface root) {
        return scene.withParts(scene.getCamera(), scene.getLights(), List.of(root));
    }
}
