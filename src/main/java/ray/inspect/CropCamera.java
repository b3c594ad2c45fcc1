package ray.inspect;

import ray.Ray;
import ray.camera.Camera;
import ray.math.Vec3;

/**
 * One pixel of another camera's image as a whole 1×1 image: image point (u, v) of the crop is
 * ((i + u)/nx, (j + v)/ny) of the original. With the renderer's sample positions, u = (a + ½)/n
 * on a 1×1 image, this is exactly the original pixel's (i + (a + ½)/n)/nx, to the last bit.
 */
final class CropCamera extends Camera {
    private final Camera camera;
    private final int i;
    private final int j;
    private final int width;
    private final int height;

    CropCamera(Camera camera, int i, int j, int width, int height) {
        this.camera = camera;
        this.i = i;
        this.j = j;
        this.width = width;
        this.height = height;
    }

    @Override
    public Vec3 getViewPoint() {
        return camera.getViewPoint();
    }

    @Override
    public Camera inFrameAt(Vec3 origin) {
        return new CropCamera(camera.inFrameAt(origin), i, j, width, height);
    }

    @Override
    public Ray generateRay(double imageU, double imageV) {
        return camera.generateRay((i + imageU) / width, (j + imageV) / height);
    }
}
