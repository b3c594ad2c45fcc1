package ray.endtoend;

import java.nio.file.Path;
import java.util.List;
import ray.image.Image;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneFiles;
import ray.scene.SceneLoader;

/** The scenes under scenes/, and small renders of them for the end-to-end tests. */
final class ShippedScenes {
    static final Path FOLDER = Path.of("scenes");
    /** Test renders are this wide (odd, so that the middle pixel's center is on the view axis). */
    static final int WIDTH = 65;

    private ShippedScenes() {
    }

    static List<Path> all() {
        return SceneFiles.under(FOLDER);
    }

    /** Loads the scene and shrinks its image to WIDTH pixels wide, keeping the aspect ratio (odd height). */
    static Scene loadSmall(Path file) {
        Scene scene = SceneLoader.load(file);
        int height = (int) Math.round((double) WIDTH * scene.getHeight() / scene.getWidth());
        scene.setImage(WIDTH, height % 2 == 1 ? height : height + 1);
        return scene;
    }

    static Image renderSmall(Scene scene) {
        return new Renderer(scene, 0, 2).render().image;
    }
}
