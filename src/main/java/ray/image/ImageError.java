package ray.image;

import ray.math.Vec3;

/**
 * How far an image is from a reference of the same size, in the measures the accuracy report
 * uses. Errors are over every channel of every pixel, in linear radiance:
 * <ul>
 * <li>{@code rmse}: √(mean of Δ²);</li>
 * <li>{@code maxError}: the largest |Δ|;</li>
 * <li>{@code psnr}: 10·log10(peak² / mean of Δ²) in dB, with peak = 1/exposure, the radiance the
 * tone map shows as white; +∞ for identical images;</li>
 * <li>{@code visibleShare}: the share of pixels with a channel whose display value (the tone map
 * before rounding to a byte) differs by more than 1/255.</li>
 * </ul>
 * A NaN or infinite radiance in the image counts as an infinite error, so that a broken render
 * never looks accurate.
 */
public final class ImageError {
    /** Display values further apart than this differ visibly: one step of an 8-bit channel. */
    public static final double VISIBLE = 1.0 / 255;

    public final double rmse;
    public final double maxError;
    public final double psnr;
    public final double visibleShare;

    private ImageError(double rmse, double maxError, double psnr, double visibleShare) {
        this.rmse = rmse;
        this.maxError = maxError;
        this.psnr = psnr;
        this.visibleShare = visibleShare;
    }

    public static ImageError of(Image image, Image reference, double exposure) {
        if (image.width() != reference.width() || image.height() != reference.height()) {
            throw new IllegalArgumentException("the image is " + image.width() + "x" + image.height()
                    + " but the reference is " + reference.width() + "x" + reference.height());
        }
        double sumSquares = 0;
        double max = 0;
        long visible = 0;
        for (int j = 0; j < image.height(); j++) {
            for (int i = 0; i < image.width(); i++) {
                Vec3 a = image.get(i, j);
                Vec3 b = reference.get(i, j);
                boolean seen = false;
                for (int axis = 0; axis < 3; axis++) {
                    double x = a.get(axis);
                    double y = b.get(axis);
                    double d = Double.isFinite(x) ? Math.abs(x - y) : Double.POSITIVE_INFINITY;
                    sumSquares += d * d;
                    max = Math.max(max, d);
                    seen |= !Double.isFinite(x)
                            || Math.abs(ToneMap.display(x, exposure) - ToneMap.display(y, exposure)) > VISIBLE;
                }
                visible += seen ? 1 : 0;
            }
        }
        long pixels = (long) image.width() * image.height();
        double meanSquare = sumSquares / (3 * pixels);
        double peak = 1 / exposure;
        return new ImageError(Math.sqrt(meanSquare), max, 10 * Math.log10(peak * peak / meanSquare), (double) visible / pixels);
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "RMSE %.3g, max %.3g, PSNR %.1f dB, %.2f%% of pixels visibly off",
                rmse, maxError, psnr, 100 * visibleShare);
    }
}
