package ray.render;

import ray.image.Image;

/** A finished render: the linear image, the plan it ran, what it traced and how long it took. */
public final class RenderResult {
    public final Image image;
    public final RenderPlan plan;
    public final RayStats rays;
    public final int samplesPerPixel;
    public final int threads;
    public final double seconds;

    RenderResult(Image image, RenderPlan plan, RayStats rays, int samplesPerPixel, int threads, double seconds) {
        this.image = image;
        this.plan = plan;
        this.rays = rays;
        this.samplesPerPixel = samplesPerPixel;
        this.threads = threads;
        this.seconds = seconds;
    }
}
