package ray.render;

import static ray.testing.Asserts.v;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import ray.Ray;
import ray.camera.Camera;

/** A camera for sampling tests: records every image point it is asked for and returns a ray that misses everything. */
final class RecordingCamera extends Camera {
    final List<double[]> asked = Collections.synchronizedList(new ArrayList<>());

    @Override
    public Ray generateRay(double imageU, double imageV) {
        asked.add(new double[] {imageU, imageV});
        return new Ray(v(0, 0, 0), v(0, 0, -1));
    }
}
