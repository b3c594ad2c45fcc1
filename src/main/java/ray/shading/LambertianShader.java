package ray.shading;

import ray.math.Vec3;

/**
 * What the framework keeps of a matte shader ({@link Lambertian}, whose light loop students write):
 * its diffuse color or texture, and how the 2019 conventions turn it into a BRDF (ρd/π,
 * {@link LambertianBrdf}).
 */
public abstract class LambertianShader extends DirectLighting {

    @Override
    protected Brdf brdf2019() {
        return new LambertianBrdf();
    }

    /** The course's 2019 code left a Lambertian without a diffuse color 0.2 gray. */
    @Override
    protected Vec3 defaultDiffuseColor2019() {
        return new Vec3(0.2, 0.2, 0.2);
    }
}
