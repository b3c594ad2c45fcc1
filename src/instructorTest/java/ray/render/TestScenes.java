package ray.render;

import ray.camera.Camera;
import ray.camera.OrthographicCamera;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Shader;
import ray.surface.Surface;
import ray.surface.Triangle;

/** Small scenes built in code for the renderer tests. */
final class TestScenes {
    private TestScenes() {
    }

    /** An orthographic camera at {@code viewPoint} looking down −z with up +y, its basis computed. */
    static OrthographicCamera orthographicDown(Vec3 viewPoint, double viewWidth, double viewHeight) {
        OrthographicCamera camera = new OrthographicCamera();
        camera.setViewPoint(viewPoint);
        camera.setViewWidth(viewWidth);
        camera.setViewHeight(viewHeight);
        camera.complete();
        return camera;
    }

    /** A scene with the given camera and image size; surfaces and lights are added by the caller. */
    static Scene scene(Camera camera, int width, int height) {
        Scene scene = new Scene();
        scene.setCamera(camera);
        scene.setImage(width, height);
        return scene;
    }

    /**
     * A triangle in the plane z = {@code z} that covers the square |x|, |y| ≤ 10 with room to
     * spare; its normal is +z when {@code facingUp}, else −z.
     */
    static Surface plane(double z, boolean facingUp, Shader shader) {
        Vec3 a = new Vec3(-40, -40, z);
        Vec3 b = new Vec3(40, -40, z);
        Vec3 c = new Vec3(0, 40, z);
        // (b − a) × (c − a) = (80, 0, 0) × (40, 80, 0) = (0, 0, 6400): +z; swapping b and c flips it.
        Triangle t = facingUp ? new Triangle(a, b, c) : new Triangle(a, c, b);
        t.setShader(shader);
        return t.complete();
    }
}
