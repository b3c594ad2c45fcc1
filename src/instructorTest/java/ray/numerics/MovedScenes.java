package ray.numerics;

import java.lang.reflect.Field;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.camera.Camera;
import ray.camera.PerspectiveCamera;
import ray.image.Image;
import ray.image.PngWriter;
import ray.math.Vec3;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneLoader;
import ray.shading.Light;
import ray.shading.ShadingContext;
import ray.surface.Group;
import ray.surface.Placement;
import ray.surface.Surface;

/**
 * Shipped scenes moved or scaled as a whole, for {@link SceneInvarianceTest}: every coordinate
 * goes through p ↦ s·p + T, the camera's viewPoint and lights' positions as points, the camera's
 * projDistance, viewWidth and viewHeight times s, the surfaces through one group with scale s and
 * translate T; lights' intensities times s² so that the irradiance I/r² at every point is the same.
 * The image is the same in exact arithmetic; only rounding (and any absolute epsilon) can change it.
 */
final class MovedScenes {
    private MovedScenes() {
    }

    /**
     * The shipped scene scenes/NAME.xml with every coordinate mapped by p ↦ scale·p + translate,
     * its image {@code shrink} times smaller on each side (the same view, fewer pixels).
     */
    static Scene load(String name, double scale, Vec3 translate, int shrink) {
        Scene original = SceneLoader.load(Path.of("scenes", name + ".xml"));
        List<Light> lights = new ArrayList<>();
        for (Light light : original.getLights()) {
            lights.add(new Light(light.getPosition().times(scale).plus(translate), light.getIntensity().times(scale * scale)));
        }
        Group placed = new Group();
        for (Surface surface : original.getSurfaces().children()) {
            placed.addSurface(surface);
        }
        Scene moved = original.withParts(camera((PerspectiveCamera) original.getCamera(), scale, translate), lights,
                List.of(Placement.of(translate, Vec3.ZERO, new Vec3(scale, scale, scale)).place(placed)));
        moved.setImage(original.getWidth() / shrink, original.getHeight() / shrink);
        moved.complete();
        return moved;
    }

    /** A copy of {@code camera} with its eye mapped by p ↦ scale·p + translate and its lengths times scale. */
    private static PerspectiveCamera camera(PerspectiveCamera camera, double scale, Vec3 translate) {
        PerspectiveCamera moved = new PerspectiveCamera();
        moved.setViewPoint(camera.getViewPoint().times(scale).plus(translate));
        moved.setViewDir((Vec3) field(Camera.class, camera, "viewDir"));
        moved.setViewUp((Vec3) field(Camera.class, camera, "viewUp"));
        moved.setViewWidth(scale * (Double) field(Camera.class, camera, "viewWidth"));
        moved.setViewHeight(scale * (Double) field(Camera.class, camera, "viewHeight"));
        moved.setProjDistance(scale * camera.getProjDistance());
        moved.complete();
        return moved;
    }

    /** The camera's own field: its class offers setters but no getters for most of its parameters. */
    private static Object field(Class<?> owner, Object object, String name) {
        try {
            Field f = owner.getDeclaredField(name);
            f.setAccessible(true);
            return f.get(object);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("the camera has no field " + name + " (renamed?)", e);
        }
    }

    /** The scene rendered by the renderer, as 8-bit pixels. */
    static java.awt.image.BufferedImage render(Scene scene) {
        return PngWriter.toBufferedImage(new Renderer(scene, 0, 0).render().image, scene.getExposure());
    }

    /**
     * The scene rendered as the renderer would, one sample per pixel, except that shadow rays start
     * at the hit point itself with a fixed t_min of {@code epsilon} along a unit direction (a
     * fixed-epsilon renderer). Only for scenes without reflections.
     */
    static java.awt.image.BufferedImage renderWithFixedEpsilon(Scene scene, double epsilon) {
        ShadingContext shading = new ShadingContext() {
            @Override
            public java.util.List<Light> lights() {
                return scene.getLights();
            }

            @Override
            public boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition) {
                Vec3 toLight = lightPosition.minus(hit.location);
                double distance = toLight.length();
                Ray shadow = new Ray(hit.location, toLight.times(1 / distance), epsilon, distance - epsilon);
                return !scene.getSurfaces().intersect(new IntersectionRecord(), shadow);
            }

            @Override
            public Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth) {
                throw new UnsupportedOperationException("no reflections in a fixed-epsilon render");
            }
        };
        int width = scene.getWidth();
        int height = scene.getHeight();
        Image image = new Image(width, height);
        for (int j = 0; j < height; j++) {
            for (int i = 0; i < width; i++) {
                Ray ray = scene.getCamera().generateRay((i + 0.5) / width, (j + 0.5) / height);
                IntersectionRecord hit = new IntersectionRecord();
                image.set(i, j, scene.getSurfaces().intersect(hit, ray)
                        ? hit.surface.getShader().shade(hit, ray, shading, 0) : scene.getBackColor());
            }
        }
        return PngWriter.toBufferedImage(image, scene.getExposure());
    }
}
