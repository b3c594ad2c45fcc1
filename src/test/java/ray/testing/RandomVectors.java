package ray.testing;

import java.util.Random;
import ray.math.Vec3;

/**
 * Seeded random points and directions for the property tests. Every test draws through these, so
 * a seed gives the same cases in every test that uses it, run after run.
 */
public final class RandomVectors {
    private RandomVectors() {
    }

    /** A point of the cube [−extent, extent]³, uniformly. */
    public static Vec3 randomVec(Random random, double extent) {
        return new Vec3(extent * (2 * random.nextDouble() - 1), extent * (2 * random.nextDouble() - 1),
                extent * (2 * random.nextDouble() - 1));
    }

    /** A point of the ball of {@code radius} about the origin, uniformly (by rejection from the cube). */
    public static Vec3 randomInBall(Random random, double radius) {
        while (true) {
            Vec3 v = randomVec(random, 1);
            if (v.lengthSquared() <= 1) {
                return v.times(radius);
            }
        }
    }

    /** A unit vector, uniformly over directions (rejecting points too near the center to normalize well). */
    public static Vec3 randomUnit(Random random) {
        while (true) {
            Vec3 v = randomVec(random, 1);
            double l2 = v.lengthSquared();
            if (l2 > 0.01 && l2 <= 1) {
                return v.normalized();
            }
        }
    }

    /** A random unit vector perpendicular to the unit vector {@code u}. */
    public static Vec3 perpendicularUnit(Vec3 u, Random random) {
        while (true) {
            Vec3 w = randomUnit(random);
            Vec3 across = w.minus(u.times(w.dot(u)));
            if (across.lengthSquared() > 0.01) {
                return across.normalized();
            }
        }
    }
}
