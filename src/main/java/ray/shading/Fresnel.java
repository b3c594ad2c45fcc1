package ray.shading;

/** The exact Fresnel reflectance of a dielectric for unpolarised light, as the course's microfacet BRDF uses it. */
public class Fresnel extends RefractiveIndex {

    public Fresnel() {
    }

    public Fresnel(double nt) {
        super(nt);
    }

    public double reflectance(double cosine) {
        // TODO(Task 11): return the exact Fresnel reflectance F for light meeting a facet at this angle.
        //   Return the share of unpolarised light that a smooth dielectric of refractive index getNt()
        //   reflects, for light arriving from a medium of index 1 whose direction's cosine with the facet's
        //   normal is cosine. Not Schlick's approximation: the exact formula.
        //   Conventions (the reference images depend on them):
        //   - cosine is |l·h|, from 0 to 1; with c = cosine, g² = nt² − 1 + c².
        //   - g² ≤ 0 (possible when nt < 1: total internal reflection) gives F = 1.
        //   - Otherwise, with g = √g², F = ½ ((g − c)/(g + c))² (1 + ((c(g + c) − 1)/(c(g − c) + 1))²).
        //   - nt = 1 reflects nothing (F = 0); never NaN.
        // HINTS steps
        //   1) Square the refractive index, subtract 1 and add the squared cosine.
        //   2) If that is not positive, return 1; otherwise take its square root, g.
        //   3) Return half the square of (g minus c over g plus c), times one plus the square of the second
        //      fraction of the formula above.
        // HINTS formulas
        //   1) g² = nt² − 1 + c², nt = getNt(), c = cosine.
        //   2) if g² ≤ 0, return 1; g = √g².
        //   3) F = ½ ((g − c)/(g + c))² (1 + ((c(g + c) − 1)/(c(g − c) + 1))²).
        // END HINTS
        // BEGIN SOLUTION
        double nt = getNt();
        double c = cosine;
        double g2 = nt * nt - 1 + c * c;
        if (!(g2 > 0)) {
            return 1;
        }
        double g = Math.sqrt(g2);
        double first = (g - c) / (g + c);
        double second = (c * (g + c) - 1) / (c * (g - c) + 1);
        return 0.5 * first * first * (1 + second * second);
        // END SOLUTION
        // STUB: return 0;
    }
}
