package ray.accuracy;

import java.awt.image.BufferedImage;
import ray.image.Image;
import ray.image.ImageError;

/** What one setting of a sweep cost and how wrong it was, in one scene. */
public final class Run {
    public final String sweep;
    public final Setting setting;
    /** Wall time of rendering the study's window, over repeated runs. */
    public final Timing timing;
    /** Rays traced by one render of the window (camera, shadow and reflection). */
    public final long rays;
    /** The window's render against the converged reference. */
    public final ImageError error;
    /** The window as this setting renders it. */
    public final Image window;
    /**
     * For a choice sweep: the share of the whole image's pixels that differ visibly from the
     * sweep's baseline rendered the same way (acne, leaks, lost silhouettes); NaN for the samples
     * sweep, which has no baseline.
     */
    public final double defects;
    /** Where those pixels are: a heat map of the whole image against the baseline, or null when none differ. */
    public final BufferedImage defectMap;

    Run(String sweep, Setting setting, Timing timing, long rays, ImageError error, Image window, double defects,
            BufferedImage defectMap) {
        this.sweep = sweep;
        this.setting = setting;
        this.timing = timing;
        this.rays = rays;
        this.error = error;
        this.window = window;
        this.defects = defects;
        this.defectMap = defectMap;
    }

    public double seconds() {
        return timing.medianSeconds;
    }
}
