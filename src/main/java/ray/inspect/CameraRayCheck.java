package ray.inspect;

import ray.Ray;
import ray.assignment.Assignment;
import ray.camera.Camera;

/**
 * Says what is wrong with a camera ray that cannot see anything, in the words of the task that
 * makes it: the handout's stub returns an empty segment (start 0 = end 0), and a half-written
 * generateRay returns null, a zero direction or NaN.
 */
public final class CameraRayCheck {
    private CameraRayCheck() {
    }

    /** The explanation, or null when the ray can hit something. */
    public static String problem(Camera camera, Ray ray) {
        String method = camera.getClass().getSimpleName() + ".generateRay";
        String hint = method + " is still the stub? See " + Assignment.current().todo("camera-rays") + " in " + camera.getClass().getSimpleName() + ".java";
        if (ray == null) {
            return "the camera returned no ray (null): " + hint;
        }
        if (ray.origin == null || ray.direction == null) {
            return "the camera ray has no " + (ray.origin == null ? "origin" : "direction") + " (null): " + method
                    + " must set both";
        }
        if (!ray.origin.isFinite() || !ray.direction.isFinite()) {
            return "the camera ray is not finite (origin " + Fmt.vec(ray.origin) + ", direction " + Fmt.vec(ray.direction)
                    + "): a division by zero or an uncomputed basis in " + method + "?";
        }
        if (ray.direction.lengthSquared() == 0) {
            return "the camera ray's direction is zero, so it cannot reach anything: " + method
                    + " must point it through the image-plane point (" + Assignment.current().todo("camera-rays") + ")";
        }
        if (!(ray.start < ray.end)) {
            String segment = ray.start == ray.end
                    ? "empty (start " + Fmt.num(ray.start) + " = end " + Fmt.num(ray.end) + ")"
                    : "empty (start " + Fmt.num(ray.start) + " > end " + Fmt.num(ray.end) + ")";
            return "the camera ray's segment is " + segment + ", so nothing can be hit: " + hint
                    + " (new Ray(origin, direction) makes the segment 0 to ∞)";
        }
        return null;
    }
}
