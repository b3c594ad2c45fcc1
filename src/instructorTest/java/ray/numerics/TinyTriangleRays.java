package ray.numerics;

import java.util.Random;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Triangle;

/**
 * Seeded tiny triangles seen from nearby: vertices within {@code size} of a random point of the unit
 * cube (skipping slivers whose smallest angle is under about 3°), hit by rays aimed at an interior
 * point (every barycentric at least 0.05) from 0.5–2 sizes away, crossing the plane at more than
 * about 11° (|cos| ≥ 0.2 to the normal). The direction is either the unit vector toward the target
 * (target at t = distance), as a textbook ray would carry, or the vector from the origin to the
 * target (target at t = 1), which the Ray contract allows; the textbook |det| &lt; 1e-8 test, with
 * det proportional to |d|·size², loses far more triangles with the second.
 */
final class TinyTriangleRays {
    private final Random random;
    private final double size;
    private final boolean unitDirection;
    Triangle triangle;
    Vec3 target;
    double distance;

    TinyTriangleRays(long seed, double size, boolean unitDirection) {
        this.random = new Random(seed);
        this.size = size;
        this.unitDirection = unitDirection;
    }

    /** The t at which the ray reaches the target. */
    double targetT() {
        return unitDirection ? distance : 1;
    }

    /** A new triangle, and a ray aimed inside it. */
    Ray next() {
        Vec3 center = new Vec3(random.nextDouble(), random.nextDouble(), random.nextDouble());
        Vec3 v0;
        Vec3 v1;
        Vec3 v2;
        do {
            v0 = center.plus(inCube(size));
            v1 = center.plus(inCube(size));
            v2 = center.plus(inCube(size));
        } while (smallestSine(v0, v1, v2) < 0.05);
        triangle = new Triangle(v0, v1, v2);
        double b1 = 0.05 + 0.9 * random.nextDouble();
        double b2 = 0.05 + (0.95 - b1 - 0.05) * random.nextDouble();
        target = v0.times(1 - b1 - b2).plus(v1.times(b1)).plus(v2.times(b2));
        Vec3 toward;
        do {
            toward = inCube(1).normalized();
        } while (Math.abs(toward.dot(triangle.getFaceNormal())) < 0.2);
        distance = size * (0.5 + 1.5 * random.nextDouble());
        Vec3 origin = target.minus(toward.times(distance));
        return new Ray(origin, unitDirection ? toward : target.minus(origin));
    }

    private Vec3 inCube(double extent) {
        return new Vec3(extent * (2 * random.nextDouble() - 1), extent * (2 * random.nextDouble() - 1),
                extent * (2 * random.nextDouble() - 1));
    }

    /** The sine of the triangle's smallest angle. */
    private static double smallestSine(Vec3 a, Vec3 b, Vec3 c) {
        double area2 = b.minus(a).cross(c.minus(a)).length();
        double ab = b.minus(a).length();
        double bc = c.minus(b).length();
        double ca = a.minus(c).length();
        // sin(angle at a) = 2·area / (|ab|·|ca|), and so on; the smallest angle is opposite the shortest side.
        return Math.min(area2 / (ab * ca), Math.min(area2 / (ab * bc), area2 / (bc * ca)));
    }
}
