package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * A stand-in surface for the Group tests: every ray "hits" it at one fixed t, if that t lies
 * inside the ray's open segment (start, end), with a normal, barycentrics and texture coordinates
 * of the test's choice.
 * It lets Group be tested without Sphere or Triangle, so the tasks can be done in any order.
 */
public final class FixedHitSurface extends Surface {
    private final String name;
    private final double t;
    private final Vec3 normal;
    private final double beta;
    private final double gamma;
    private final double texU;
    private final double texV;

    /** A surface called {@code name} that is hit at {@code t} with {@code normal} (β = γ = 0). */
    public FixedHitSurface(String name, double t, Vec3 normal) {
        this(name, t, normal, 0, 0);
    }

    public FixedHitSurface(String name, double t, Vec3 normal, double beta, double gamma) {
        this(name, t, normal, beta, gamma, 0, 0);
    }

    public FixedHitSurface(String name, double t, Vec3 normal, double beta, double gamma, double texU, double texV) {
        this.name = name;
        this.t = t;
        this.normal = normal;
        this.beta = beta;
        this.gamma = gamma;
        this.texU = texU;
        this.texV = texV;
    }

    public double hitT() {
        return t;
    }

    public Vec3 hitNormal() {
        return normal;
    }

    /** Keeps the Surface contract: fills the record only on a hit, only for start &lt; t &lt; end. */
    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        if (!(ray.start < t && t < ray.end)) {
            return false;
        }
        out.t = t;
        out.location = ray.pointAt(t);
        out.normal = normal;
        out.surface = this;
        out.beta = beta;
        out.gamma = gamma;
        out.texU = texU;
        out.texV = texV;
        return true;
    }

    /** "surface B (hit at t = 4.0)", so that a failure message names the surface that was reported. */
    @Override
    public String toString() {
        return "surface " + name + " (hit at t = " + t + ")";
    }
}
