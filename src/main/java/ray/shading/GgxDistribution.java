package ray.shading;

import ray.math.Vec3;

/** The GGX (Trowbridge–Reitz) distribution of microfacet normals, with its exact Smith masking term. */
public class GgxDistribution extends MicrofacetDistribution {
    public GgxDistribution() {
    }

    public GgxDistribution(double alpha) {
        super(alpha);
    }

    @Override
    public String name() {
        return GGX;
    }

    @Override
    public double normalDistribution(Vec3 n, Vec3 h) {
        // TODO(Task 11): return the GGX distribution D(h) of facet normals.
        //   Return how densely the surface's tiny facets point along h: largest for h along the normal,
        //   with a long tail toward grazing angles, as wide as the roughness getAlpha() says.
        //   Conventions (the reference images depend on them):
        //   - n and h are unit vectors; θ is the angle between them.
        //   - D = α² / (π cos⁴θ (α² + tan²θ)²) for h above the surface, and 0 for h on or below it.
        //   - Never NaN or infinite: at 90° from n, tanθ is infinite but D is not (multiply cos⁴θ in).
        // HINTS steps
        //   1) Take the cosine between h and the normal; if it is not positive, return 0.
        //   2) Take the squared sine (the squared length of the cross product of the two unit vectors).
        //   3) The fourth power of the cosine times the square of (squared roughness plus squared tangent)
        //      is the square of (squared roughness times squared cosine plus squared sine).
        //   4) Divide the squared roughness by π times that.
        // HINTS formulas
        //   1) c = n·h; if c ≤ 0, return 0.
        //   2) s² = |n × h|²: n.cross(h).lengthSquared().
        //   3) cos⁴θ (α² + tan²θ)² = (α² c² + s²)², α = getAlpha().
        //   4) D = α² / (π (α² c² + s²)²).
        // END HINTS
        // BEGIN SOLUTION
        double c = n.dot(h);
        if (!(c > 0)) {
            return 0;
        }
        double alpha2 = getAlpha() * getAlpha();
        double sum = alpha2 * c * c + n.cross(h).lengthSquared();
        return alpha2 / (Math.PI * sum * sum);
        // END SOLUTION
        // STUB: return 0;
    }

    @Override
    public double masking(Vec3 x, Vec3 n, Vec3 h) {
        // TODO(Task 11): return GGX's masking term G1(x, h).
        //   Return the share of the facets with normal h that the direction x sees, not hidden by others:
        //   1 along the normal, falling to 0 as x grazes the surface.
        //   Conventions (the reference images depend on them):
        //   - x, n and h are unit vectors; θ is the angle between x and n.
        //   - G1 = 0 unless x·h and x·n have the same sign (x on the facet's side as on the surface's).
        //   - G1 = 2 / (1 + √(1 + α² tan²θ)); never NaN or infinite, even where tanθ is.
        // HINTS steps
        //   1) If the cosines of x with h and with n do not have the same sign, return 0.
        //   2) Take the cosine of x with the normal, as a positive number, and the sine (the length of the
        //      cross product).
        //   3) Multiply the fraction's top and bottom by the cosine, so that no tangent is needed: twice the
        //      cosine over the cosine plus the square root of (squared cosine plus squared roughness times
        //      squared sine).
        // HINTS formulas
        //   1) if (x·h)(x·n) ≤ 0, return 0.
        //   2) c = |x·n|, s = |x × n|.
        //   3) G1 = 2c / (c + √(c² + α² s²)), α = getAlpha().
        // END HINTS
        // BEGIN SOLUTION
        double xn = x.dot(n);
        if (!(x.dot(h) * xn > 0)) {
            return 0;
        }
        double c = Math.abs(xn);
        double alpha = getAlpha();
        double s2 = x.cross(n).lengthSquared();
        return 2 * c / (c + Math.sqrt(c * c + alpha * alpha * s2));
        // END SOLUTION
        // STUB: return 0;
    }
}
