package ray.accuracy;

import ray.scene.Scene;
import ray.shading.Light;
import ray.shading.Shader;
import ray.surface.Surface;

/** Copies of a loaded scene that differ in one part, for rendering the same scene several ways. */
public final class SceneCopy {
    private SceneCopy() {
    }

    /** {@code scene} with {@code root} as its only surface; camera, image, lights and settings shared. */
    public static Scene withSurfaces(Scene scene, Surface root) {
        Scene copy = new Scene();
        copy.setName(scene.getName());
        copy.setCamera(scene.getCamera());
        copy.setImage(scene.getWidth(), scene.getHeight());
        copy.setExposure(scene.getExposure());
        copy.setBackColor(scene.getBackColor());
        copy.setSamples(scene.getSamples());
        for (Light light : scene.getLights()) {
            copy.addLight(light);
        }
        for (Shader shader : scene.getShaders()) {
            copy.addShader(shader);
        }
        copy.addSurface(root);
        return copy;
    }
}
