package ray.trace;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.render.SecondaryRays;
import ray.scene.Scene;
import ray.shading.Light;
import ray.shading.Tracer;

/**
 * The renderer's tracing rules (closest hit by the scene's group, background on a miss, shadow
 * and reflection rays from {@link SecondaryRays}) for shading one hit outside the renderer. It can
 * show a shader only some of the lights, or pretend nothing casts shadows, to take a pixel's
 * radiance apart light by light.
 */
final class TraceTracer implements Tracer {
    private final Scene scene;
    private final List<Light> lights;
    private final boolean ignoreShadows;
    int shadowRays;
    int reflectionRays;

    TraceTracer(Scene scene) {
        this(scene, scene.getLights(), false);
    }

    private TraceTracer(Scene scene, List<Light> lights, boolean ignoreShadows) {
        this.scene = scene;
        this.lights = lights;
        this.ignoreShadows = ignoreShadows;
    }

    /** The same scene lit by {@code light} alone; with {@code ignoreShadows}, as if nothing blocked it. */
    TraceTracer onlyLight(Light light, boolean ignoreShadows) {
        return new TraceTracer(scene, List.of(light), ignoreShadows);
    }

    /** The radiance along a ray, as the renderer computes it at this recursion depth. */
    Vec3 radiance(Ray ray, int depth) {
        IntersectionRecord hit = new IntersectionRecord();
        if (!scene.getSurfaces().intersect(hit, ray)) {
            return scene.getBackColor();
        }
        return hit.surface.getShader().shade(hit, ray, this, depth);
    }

    @Override
    public List<Light> lights() {
        return lights;
    }

    @Override
    public boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition) {
        shadowRays++;
        return ignoreShadows || !scene.getSurfaces().intersect(new IntersectionRecord(), SecondaryRays.shadowRay(hit, lightPosition));
    }

    @Override
    public Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth) {
        reflectionRays++;
        return radiance(SecondaryRays.reflectionRay(hit, direction), depth);
    }
}
