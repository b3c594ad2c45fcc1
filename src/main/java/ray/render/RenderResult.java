package ray.render;

import ray.image.Image;

/**
 * A finished render: the linear image, what its pixels show when that was asked for, the plan it
 * ran, what it traced and how long it took.
 */
public final class RenderResult {
    public final Image image;
    /** What each pixel's camera rays hit first, from {@link Renderer#renderWithKinds()}; null from {@link Renderer#render()}. */
    public final PixelKinds kinds;
    public final RenderPlan plan;
    public final RayStats rays;
    public final int samplesPerPixel;
    public final int threads;
    public final double seconds;

    RenderResult(Image image, PixelKinds kinds, RenderPlan plan, RayStats rays, int samplesPerPixel, int threads, double seconds) {
        this.image = image;
        this.kinds = kinds;
        this.plan = plan;
        this.rays = rays;
        this.samplesPerPixel = samplesPerPixel;
        this.threads = threads;
        this.seconds = seconds;
    }
}
