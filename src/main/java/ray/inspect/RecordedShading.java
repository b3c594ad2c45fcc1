package ray.inspect;

import java.util.List;
import ray.IntersectionRecord;
import ray.math.Vec3;
import ray.render.SceneShading;
import ray.scene.Scene;
import ray.shading.Light;

/**
 * The renderer's own tracing ({@link SceneShading}) for shading one hit outside the renderer,
 * counting the shadow and reflection rays it traces. It can show a shader only some of the lights,
 * or pretend nothing casts shadows, to take a pixel's radiance apart light by light.
 */
final class RecordedShading extends SceneShading {
    private final List<Light> lights;
    private final boolean ignoreShadows;
    int shadowRays;
    int reflectionRays;

    RecordedShading(Scene scene) {
        this(scene, scene.getLights(), false);
    }

    private RecordedShading(Scene scene, List<Light> lights, boolean ignoreShadows) {
        super(scene);
        this.lights = lights;
        this.ignoreShadows = ignoreShadows;
    }

    /** The same scene lit by {@code light} alone; with {@code ignoreShadows}, as if nothing blocked it. */
    RecordedShading onlyLight(Light light, boolean ignoreShadows) {
        return new RecordedShading(scene(), List.of(light), ignoreShadows);
    }

    @Override
    public List<Light> lights() {
        return lights;
    }

    @Override
    public boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition) {
        shadowRays++;
        return ignoreShadows || super.unoccluded(hit, lightPosition);
    }

    @Override
    public Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth) {
        reflectionRays++;
        return super.radiance(hit, direction, depth);
    }
}
