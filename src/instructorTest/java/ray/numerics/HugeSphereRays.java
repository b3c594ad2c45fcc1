package ray.numerics;

import java.util.Random;
import ray.Ray;
import ray.math.Vec3;

/**
 * Seeded rays that start about 1 unit outside a huge sphere and head into it, shared by
 * HugeSphereNearRootTest and SphereSweep.
 *
 * <p>The origin sits at height h in [0.5, 1.5) above the surface; the direction points down, within
 * 45° of the inward normal, with a length in [0.5, 2) (ray directions are not unit). Two placements:
 * <ul>
 * <li>{@link #ground}: the sphere's center is (0, −R, 0) and the origin's coordinates are multiples of
 * 1/64 within a few units of the world origin, like a camera above a huge ground sphere. Then f·f
 * and r² are exact doubles, so c = f·f − r² is exact, and the stable quadratic's c/q keeps the near
 * root to a few ulps.
 * <li>{@link #anywhere}: the center anywhere in [−2R, 2R]³ and the origin above a random point of
 * the surface. Then o − c and f·f round at the scale R, and the near root t ≈ 1 can only be as
 * accurate as those roundings allow (ExactSphere.conditionBound).
 * </ul>
 */
final class HugeSphereRays {
    private final Random random;
    private final double radius;
    private final boolean ground;

    private HugeSphereRays(long seed, double radius, boolean ground) {
        this.random = new Random(seed);
        this.radius = radius;
        this.ground = ground;
    }

    static HugeSphereRays ground(long seed, double radius) {
        return new HugeSphereRays(seed, radius, true);
    }

    static HugeSphereRays anywhere(long seed, double radius) {
        return new HugeSphereRays(seed, radius, false);
    }

    SphereCase next() {
        Vec3 center;
        Vec3 origin;
        if (ground) {
            center = new Vec3(0, -radius, 0);
            origin = new Vec3(sixtyFourths(-8, 8), sixtyFourths(0.5, 1.5), sixtyFourths(-8, 8));
        } else {
            center = new Vec3(uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)).times(radius);
            origin = center.plus(randomUnit().times(radius + uniform(0.5, 1.5)));
        }
        Vec3 up = origin.minus(center).normalized();
        Vec3 side = randomUnit();
        side = side.minus(up.times(side.dot(up))).normalized();
        double tilt = uniform(0, Math.PI / 4);
        Vec3 direction = up.times(-Math.cos(tilt)).plus(side.times(Math.sin(tilt))).times(uniform(0.5, 2));
        return new SphereCase(center, radius, new Ray(origin, direction));
    }

    private double sixtyFourths(double low, double high) {
        return Math.floor(uniform(low, high) * 64) / 64;
    }

    private double uniform(double low, double high) {
        return low + (high - low) * random.nextDouble();
    }

    private Vec3 randomUnit() {
        return new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalized();
    }
}
