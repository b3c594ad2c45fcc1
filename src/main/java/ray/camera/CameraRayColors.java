package ray.camera;

import ray.Ray;
import ray.image.Image;
import ray.math.Vec3;

/**
 * A picture of a camera's rays alone, before any surface works ({@code ray1 render --camera-rays}):
 * each pixel shows where its ray crosses the image plane, so Task 1 has a picture of its own.
 *
 * <p>For the ray (o, d) of a pixel, the point p where the line o + t·d crosses the image plane
 * (projDistance in front of viewPoint for a perspective camera, through viewPoint for an
 * orthographic one) gives the image-plane coordinates planeU = (p − e)·u and planeV = (p − e)·v,
 * e being viewPoint. The pixel's red is planeU / viewWidth + ½ and its green planeV / viewHeight + ½,
 * so correct rays paint the same picture for every camera: black at the lower left, red at the lower
 * right, green at the upper left, yellow at the upper right. Blue shows how far a ray is from its kind's
 * rule: a perspective ray that does not start at viewPoint (|o − e| in units of the larger view
 * side), an orthographic ray not parallel to viewDir (|d/|d| + w|); correct rays have none.
 * Magenta marks a ray that cannot see anything: none, an empty segment (the stubs' rays), a
 * zero or non-finite direction, or one that does not point forward.
 */
public final class CameraRayColors {
    /** The color of a ray that cannot see anything. */
    public static final Vec3 UNUSABLE = new Vec3(1, 0, 1);

    private CameraRayColors() {
    }

    /** The picture of {@code camera}'s rays through the centers of a width × height image's pixels. */
    public static Image render(Camera camera, int width, int height) {
        Image image = new Image(width, height);
        for (int j = 0; j < height; j++) {
            for (int i = 0; i < width; i++) {
                Ray ray = camera.generateRay((i + 0.5) / width, (j + 0.5) / height);
                image.set(i, j, colorOf(camera, ray));
            }
        }
        return image;
    }

    /** The color of one ray of {@code camera} (see the class comment). */
    static Vec3 colorOf(Camera camera, Ray ray) {
        if (ray == null || ray.origin == null || ray.direction == null || !ray.origin.isFinite() || !ray.direction.isFinite()
                || !(ray.start < ray.end)) {
            return UNUSABLE;
        }
        Vec3 forward = camera.w.negate();
        double along = ray.direction.dot(forward);
        if (!(along > 0)) {
            return UNUSABLE;
        }
        boolean perspective = camera instanceof PinholeCamera;
        double planeDistance = perspective ? ((PinholeCamera) camera).getProjDistance() : 0;
        double t = (planeDistance - ray.origin.minus(camera.viewPoint).dot(forward)) / along;
        Vec3 onPlane = ray.pointAt(t).minus(camera.viewPoint);
        double red = onPlane.dot(camera.u) / camera.viewWidth + 0.5;
        double green = onPlane.dot(camera.v) / camera.viewHeight + 0.5;
        double blue = perspective
                ? ray.origin.minus(camera.viewPoint).length() / Math.max(camera.viewWidth, camera.viewHeight)
                : ray.direction.normalized().minus(forward).length();
        return new Vec3(clamp(red), clamp(green), clamp(blue));
    }

    private static double clamp(double x) {
        return Math.max(0, Math.min(1, x));
    }
}
