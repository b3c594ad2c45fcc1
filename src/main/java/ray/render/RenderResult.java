package ray.render;

import ray.image.Image;

/** A finished render: the linear image, what it traced and how long it took. */
public final class RenderResult {
    public final Image image;
    public final RayStats rays;
    public final int samplesPerPixel;
    public final int threads;
    public final double seconds;

    RenderResult(Image image, RayStats rays, int samplesPerPixel, int threads, double seconds) {
        this.image = image;
        this.rays = rays;
        this.samplesPerPixel = samplesPerPixel;
        this.threads = threads;
        this.seconds = seconds;
    }
}
