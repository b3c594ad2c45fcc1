package ray.inspect;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Surface;

/**
 * A test surface hit at t = 1 by any ray whose segment holds 1, as the intersect contract says,
 * reporting the normal it was given (one that is not unit length, to see the trace flag it).
 */
final class Wall extends Surface {
    private final Vec3 normal;

    Wall(Vec3 normal) {
        this.normal = normal;
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        if (!(ray.start < 1 && 1 < ray.end)) {
            return false;
        }
        out.t = 1;
        out.location = ray.pointAt(1);
        out.normal = normal;
        out.surface = this;
        return true;
    }

    @Override
    public String toString() {
        return "Wall";
    }
}
