package ray.shading;

import ray.math.Vec3;

/**
 * A bidirectional reflectance distribution function, as the course's 2019 conventions shade with:
 * the ratio f(l, v) of the radiance reflected toward v to the irradiance arriving from l, per color
 * channel. {@link ReflectionShader} multiplies it by I·max(0, n·l)/r² for each light.
 */
public interface Brdf {
    /**
     * f(l, v) at a point with unit normal {@code n}, for the unit directions {@code l} (toward the
     * light) and {@code v} (toward the viewer), with diffuse reflectance {@code rhoD} (the shader's
     * diffuse color, or its texture's color at the point).
     */
    Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v);

    /** The formula, as {@code ray1 trace} writes it: "ρd/π". */
    String formula();

    /** Checks nothing: a BRDF's parameters come ready from its shader. */
    default void complete() {
    }
}
