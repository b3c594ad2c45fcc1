package ray.shading;

/**
 * What the framework keeps of the microfacet BRDF's Fresnel factor ({@link Fresnel}, whose
 * {@code reflectance} students write): the refractive index nt of the material under the surface,
 * with the light arriving from a medium of index 1.
 */
public abstract class RefractiveIndex {
    private double nt = 1.5;

    /** An index set later (the grader's copy, whose fields are copied in). */
    protected RefractiveIndex() {
    }

    /** @param nt the material's refractive index, a number > 0 (glass about 1.5; 1 reflects nothing) */
    protected RefractiveIndex(double nt) {
        if (!(nt > 0) || Double.isInfinite(nt)) {
            throw new IllegalArgumentException("nt is " + nt + "; expected a refractive index > 0");
        }
        this.nt = nt;
    }

    /** nt, the refractive index. */
    public double getNt() {
        return nt;
    }

    /** Checks nothing: its constructor has checked its index. */
    public void complete() {
    }

    @Override
    public String toString() {
        return "exact dielectric Fresnel (nt = " + nt + ")";
    }
}
