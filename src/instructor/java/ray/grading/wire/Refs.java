package ray.grading.wire;

import ray.image.Image;
import ray.surface.Surface;

/**
 * How one side names objects in messages: each side maps its own objects (the judge's stand-ins
 * and surfaces, the worker's twins and proxies) to handles the other side knows.
 */
public interface Refs {
    void writeSurface(WireOut out, Surface surface);

    Surface readSurface(WireIn in);

    void writeImage(WireOut out, Image image);

    Image readImage(WireIn in);
}
