package ray.inspect;

import ray.image.ToneMap;
import ray.math.Vec3;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.surface.Surface;

/**
 * A pixel's radiance as the renderer computes it (the real Renderer, run on a 1×1 crop of the
 * image around the pixel, so every sample is where the full render puts it), and its 8-bit value
 * as the PNG writer stores it.
 */
final class PixelValue {
    final Vec3 radiance;
    final int[] rgb8;
    final int samples;
    final long shadowRays;
    final long reflectionRays;

    private PixelValue(Vec3 radiance, int[] rgb8, int samples, long shadowRays, long reflectionRays) {
        this.radiance = radiance;
        this.rgb8 = rgb8;
        this.samples = samples;
        this.shadowRays = shadowRays;
        this.reflectionRays = reflectionRays;
    }

    /** Renders pixel (i, j), j from the bottom, with the scene's samples or {@code samplesOverride} if positive. */
    static PixelValue render(Scene scene, int i, int j, int samplesOverride) {
        Scene crop = new Scene();
        crop.setName(scene.getName());
        crop.setCamera(new CropCamera(scene.getCamera(), i, j, scene.getWidth(), scene.getHeight()));
        crop.setImage(1, 1);
        crop.setExposure(scene.getExposure());
        crop.setBackColor(scene.getBackColor());
        crop.setSamples(scene.getSamples());
        scene.getLights().forEach(crop::addLight);
        for (Surface s : scene.getSurfaces().children()) {
            crop.addSurface(s);
        }
        RenderResult result = new Renderer(crop, samplesOverride, 1).render();
        Vec3 radiance = result.image.get(0, 0);
        double exposure = scene.getExposure();
        int[] rgb8 = {ToneMap.toByte(radiance.x, exposure), ToneMap.toByte(radiance.y, exposure), ToneMap.toByte(radiance.z, exposure)};
        return new PixelValue(radiance, rgb8, result.samplesPerPixel, result.rays.shadow, result.rays.reflection);
    }
}
