package ray.shading;

import ray.math.Vec3;

/** The Beckmann distribution of microfacet normals, with Smith's masking in the rational form the course used. */
public class BeckmannDistribution extends MicrofacetDistribution {
    public BeckmannDistribution() {
    }

    public BeckmannDistribution(double alpha) {
        super(alpha);
    }

    @Override
    public String name() {
        return BECKMANN;
    }

    @Override
    public double normalDistribution(Vec3 n, Vec3 h) {
        // TODO(Task 11): return the Beckmann distribution D(h) of facet normals.
        //   Return how densely the surface's tiny facets point along h: largest for h along the normal,
        //   falling off like a Gaussian in the slope, as steeply as the roughness getAlpha() says.
        //   Conventions (the reference images depend on them):
        //   - n and h are unit vectors; θ is the angle between them.
        //   - D = exp(−tan²θ / α²) / (π α² cos⁴θ) for h above the surface, and 0 for h on or below it.
        //   - Never NaN or infinite: h at 90° from n, or a tiny α, gives 0 where the exponential vanishes.
        // HINTS steps
        //   1) Take the cosine between h and the normal; if it is not positive, return 0.
        //   2) Find the squared tangent of the angle: the squared sine over the squared cosine (the squared
        //      sine is the squared length of the cross product of the two unit vectors).
        //   3) Take the exponential of minus that over the squared roughness; if it is zero, return 0.
        //   4) Divide it by π, the squared roughness and the cosine to the fourth power.
        // HINTS formulas
        //   1) c = n·h; if c ≤ 0, return 0.
        //   2) tan²θ = |n × h|² / c²: n.cross(h).lengthSquared() / (c * c).
        //   3) e = exp(−tan²θ / α²), α = getAlpha(); if e = 0, return 0.
        //   4) D = e / (π α² c⁴).
        // END HINTS
        // BEGIN SOLUTION
        double c = n.dot(h);
        if (!(c > 0)) {
            return 0;
        }
        double alpha2 = getAlpha() * getAlpha();
        double tan2 = n.cross(h).lengthSquared() / (c * c);
        double falloff = Math.exp(-tan2 / alpha2);
        // Where the exponential has underflowed, c⁴ may have too: 0, never 0/0.
        return falloff == 0 ? 0 : falloff / (Math.PI * alpha2 * (c * c) * (c * c));
        // END SOLUTION
        // STUB: return 0;
    }

    @Override
    public double masking(Vec3 x, Vec3 n, Vec3 h) {
        // TODO(Task 11): return Beckmann's masking term G1(x, h), in the course's rational approximation.
        //   Return the share of the facets with normal h that the direction x sees, not hidden by others:
        //   1 when x is near the normal, falling toward 0 as x grazes the surface.
        //   Conventions (the reference images depend on them):
        //   - x, n and h are unit vectors; θ is the angle between x and n, and a = 1 / (α tanθ).
        //   - G1 = 0 unless x·h and x·n have the same sign (x on the facet's side as on the surface's).
        //   - G1 = 1 for a ≥ 1.6 (normal incidence, tanθ = 0, is a = ∞: 1), else
        //     (3.535a + 2.181a²) / (1 + 2.276a + 2.577a²): the course's rational fit, not the erf form.
        // HINTS steps
        //   1) If the cosines of x with h and with n do not have the same sign, return 0.
        //   2) Take the cosine of x with the normal, as a positive number, and the sine (the length of the
        //      cross product); if the sine is zero, x is the normal: return 1.
        //   3) Divide the cosine by the roughness times the sine: that is a.
        //   4) If a is at least 1.6, return 1; otherwise return the rational fit of a.
        // HINTS formulas
        //   1) if (x·h)(x·n) ≤ 0, return 0.
        //   2) c = |x·n|, s = |x × n|; if s = 0, return 1.
        //   3) a = c / (α s), α = getAlpha().
        //   4) a ≥ 1.6: 1; else (3.535a + 2.181a²) / (1 + 2.276a + 2.577a²).
        // END HINTS
        // BEGIN SOLUTION
        double xn = x.dot(n);
        if (!(x.dot(h) * xn > 0)) {
            return 0;
        }
        double sine = x.cross(n).length();
        if (sine == 0) {
            return 1; // along the normal: tanθ = 0, a = ∞
        }
        double a = Math.abs(xn) / (getAlpha() * sine);
        if (a >= 1.6) {
            return 1;
        }
        return (3.535 * a + 2.181 * a * a) / (1 + 2.276 * a + 2.577 * a * a);
        // END SOLUTION
        // STUB: return 0;
    }
}
