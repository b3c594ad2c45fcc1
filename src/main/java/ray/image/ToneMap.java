package ray.image;

/**
 * Linear radiance to an 8-bit display value, as the course's reference images are made:
 * exposure × L, clamp to [0, 1], gamma 1/2.2, then floor(255·x + ½).
 */
public final class ToneMap {
    public static final double GAMMA = 2.2;

    private ToneMap() {
    }

    public static int toByte(double radiance, double exposure) {
        return (int) Math.floor(255 * display(radiance, exposure) + 0.5);
    }

    /** The display value in [0, 1] before it is rounded to a byte: (exposure × L)^(1/2.2), clamped. */
    public static double display(double radiance, double exposure) {
        double x = exposure * radiance;
        // NaN (a broken shader) shows as black rather than poisoning the file.
        if (!(x > 0)) {
            return 0;
        }
        if (x >= 1) {
            return 1;
        }
        return Math.pow(x, 1 / GAMMA);
    }
}
