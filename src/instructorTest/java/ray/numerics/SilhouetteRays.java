package ray.numerics;

import java.util.Random;
import ray.Ray;
import ray.math.Vec3;

/**
 * Seeded rays that graze a unit sphere far away, shared by FarSphereSilhouetteTest and SphereSweep.
 *
 * <p>Each case puts the sphere's center at {@code distance} from the world origin in a random
 * direction, starts the ray at a random point of the cube [−1, 1]³ and aims it, with a unit
 * direction, so that its impact parameter (the distance from the center to the ray's line) is
 * r·(1 + δ), δ uniform in ±spread ({@link #NEAR_SILHOUETTE} for the catalogue: half the rays just
 * hit, half just miss; {@link #WHOLE_DISK} spreads them over twice the sphere's disk).
 * Rounding the direction to doubles moves the impact parameter by about ε·distance, which is why the
 * oracle classifies the rounded inputs, not the intended ones.
 */
final class SilhouetteRays {
    /** Impact parameters within ±0.1% of the radius: the catalogue's case. */
    static final double NEAR_SILHOUETTE = 1e-3;
    /** Impact parameters uniform in [0, 2r]: most rays are far from the silhouette. */
    static final double WHOLE_DISK = 1;
    static final double RADIUS = 1;

    private final Random random;
    private final double distance;
    private final double spread;

    SilhouetteRays(long seed, double distance, double spread) {
        this.random = new Random(seed);
        this.distance = distance;
        this.spread = spread;
    }

    SphereCase next() {
        Vec3 origin = new Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
        Vec3 center = randomUnit().times(distance);
        Vec3 toCenter = center.minus(origin);
        double centerDistance = toCenter.length();
        Vec3 w = toCenter.times(1 / centerDistance);
        Vec3 side = randomUnit();
        Vec3 perpendicular = side.minus(w.times(side.dot(w))).normalized();
        // A direction at angle θ from w with centerDistance·sin θ = impact parameter.
        double impact = RADIUS * (1 + uniform(-spread, spread));
        double sin = impact / centerDistance;
        double cos = Math.sqrt(1 - sin * sin);
        Vec3 direction = w.times(cos).plus(perpendicular.times(sin));
        return new SphereCase(center, RADIUS, new Ray(origin, direction));
    }

    private double uniform(double low, double high) {
        return low + (high - low) * random.nextDouble();
    }

    private Vec3 randomUnit() {
        return new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalized();
    }
}
