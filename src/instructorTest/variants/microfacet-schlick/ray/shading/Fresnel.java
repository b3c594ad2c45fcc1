package ray.shading;

/** Known wrong: Schlick's approximation R0 + (1 − R0)(1 − c)^5 with R0 = ((nt − 1)/(nt + 1))², not the exact Fresnel factor. */
public class Fresnel extends RefractiveIndex {

    public Fresnel() {
    }

    public Fresnel(double nt) {
        super(nt);
    }

    public double reflectance(double cosine) {
        double nt = getNt();
        double r0 = (nt - 1) / (nt + 1);
        r0 = r0 * r0;
        return r0 + (1 - r0) * Math.pow(1 - cosine, 5);
    }
}
