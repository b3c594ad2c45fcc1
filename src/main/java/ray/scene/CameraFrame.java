package ray.scene;

import java.util.ArrayList;
import java.util.List;
import ray.math.Vec3;
import ray.shading.Light;
import ray.surface.Surface;

/**
 * A scene moved so that its camera sits at the origin, which is how the renderer sees every scene
 * (pbrt-v4 renders in such a "camera-world" space by default, for the same reason).
 *
 * <p>Why: a double carries about 16 digits of a coordinate's whole size, so a scene of size 1 placed
 * 10¹² from the origin keeps only about 4 digits of its own detail in every hit point computed
 * there, and the offsets that keep new rays off their surface must be sized to that error
 * (HitGeometry's scale). Subtracting the camera's position once, in double, when the render
 * starts turns each coordinate into its offset from the eye: the subtraction rounds once (and not
 * at all where the two are within a factor of 2, by Sterbenz's lemma), and from then on rays
 * start at the origin and hit points are as exact as the scene's size allows, wherever it sits.
 * Directions, sizes, normals and texture coordinates do not change; lights move with the rest.
 *
 * <p>Every position moves: spheres' and cylinders' centers, triangles', boxes' and meshes'
 * vertices, lights, and the translation of each placed group at the top (its contents stay in
 * their own coordinates). Shaders and textures are shared with the original, which is left as it was.
 */
public final class CameraFrame {
    private CameraFrame() {
    }

    /** {@code scene} seen from a camera at the origin; the scene itself when its camera is already there. */
    static Scene of(Scene scene) {
        Vec3 eye = scene.getCamera().getViewPoint();
        if (eye.x == 0 && eye.y == 0 && eye.z == 0) {
            return scene;
        }
        return seenFrom(scene, eye);
    }

    /**
     * {@code scene} in coordinates whose origin is its point {@code eye}: every position p becomes
     * p − eye, by the rules above. (With −T for {@code eye}, the scene moved by T, as the numerics
     * tests move scenes far from the origin.)
     */
    public static Scene seenFrom(Scene scene, Vec3 eye) {
        List<Light> lights = new ArrayList<>();
        for (Light light : scene.getLights()) {
            lights.add(new Light(light.getPosition().minus(eye), light.getIntensity()));
        }
        List<Surface> surfaces = new ArrayList<>();
        for (Surface child : scene.getSurfaces().children()) {
            surfaces.add(child.inFrameAt(eye));
        }
        Scene moved = scene.withParts(scene.getCamera().inFrameAt(eye), lights, surfaces);
        // A rebuilt box or mesh has new triangles, which take its shader as the loaded ones did.
        moved.complete(scene.getCourse());
        return moved;
    }
}
