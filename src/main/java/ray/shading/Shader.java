package ray.shading;

import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Turns a hit into the radiance that leaves it back along the ray. */
public abstract class Shader {
    /**
     * @param hit   the closest hit of {@code ray}
     * @param ray   the ray that found it (its direction need not be unit length)
     * @param depth the ray's recursion depth, 0 for camera rays
     * @return linear RGB radiance toward the ray's origin
     */
    public abstract Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth);

    // What ray1 trace and the explore page show of a shader: each says its own, null where it has none,
    // so the inspection code needs no list of shader types.

    /** Its diffuse color kd, or null. */
    public Vec3 getDiffuseColor() {
        return null;
    }

    /** The texture whose color replaces kd, or null. */
    public Texture getTexture() {
        return null;
    }

    /** kd at a hit (a texture's color there, else the diffuse color), or null for a shader without kd. */
    public Vec3 diffuseColorAt(IntersectionRecord hit) {
        return null;
    }

    /** Its specular color ks, or null. */
    public Vec3 getSpecularColor() {
        return null;
    }

    /** Its specular exponent p, or null. */
    public Double getExponent() {
        return null;
    }

    /** The effects this shader itself calls for (a glaze: reflection; Phong: lighting, shadows, specular). */
    public Set<Effect> effects() {
        return Set.of();
    }

    /** The shaders this one shades with (a glaze's substrate), whose effects it calls for too. */
    public List<Shader> parts() {
        return List.of();
    }

    /** This shader's effects and those of its parts, recursively. */
    public final Set<Effect> allEffects() {
        Set<Effect> all = EnumSet.noneOf(Effect.class);
        all.addAll(effects());
        for (Shader part : parts()) {
            all.addAll(part.allEffects());
        }
        return all;
    }

    /** Unit vector from the hit toward where the ray came from. */
    protected static Vec3 towardEye(Ray ray) {
        return ray.direction.normalized().negate();
    }

    @Override
    public String toString() {
        return getClass().getSimpleName();
    }
}
