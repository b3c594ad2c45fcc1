package ray.camera;

import ray.math.Vec3;

/**
 * What the framework asks of every camera besides its rays: to check its view and compute its
 * basis once the scene has set it, and to move into the camera's own frame. {@link Camera}
 * implements it, so that the classes students open hold only the camera's data and the method
 * they write; the work is {@link CameraFacts}'.
 */
public interface FrameworkCamera {
    /** Checks the view and computes the basis u, v, w; called once every property is set. */
    default void complete() {
        CameraFacts.complete((Camera) this);
    }

    /**
     * This camera in coordinates whose origin is at {@code origin} (its viewPoint becomes
     * viewPoint − origin; directions and sizes stay): a copy of every field, so that a camera
     * class's own settings come along.
     */
    default Camera inFrameAt(Vec3 origin) {
        return CameraFacts.inFrameAt((Camera) this, origin);
    }
}
