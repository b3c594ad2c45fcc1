package ray.shading;

import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.function.DoubleFunction;
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

    /**
     * Checks the shader once the scene has set its properties; the loader calls it. Nothing to check
     * by default (a shader's setters refuse bad values themselves).
     */
    public void complete() {
    }

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

    /**
     * A short name with its parameters, as {@code ray1 trace} and the explore page show it, each
     * number written by {@code number}: "Phong, kd = (1, 0, 0), ks = (0.5, 0.5, 0.5), p = 20",
     * "Lambertian, kd from Texture data/textures/earth.png". A shader with parameters of its own adds them.
     */
    public String describe(DoubleFunction<String> number) {
        StringBuilder s = new StringBuilder(toString());
        Vec3 kd = getDiffuseColor();
        Vec3 ks = getSpecularColor();
        Double p = getExponent();
        if (getTexture() != null) {
            s.append(", kd from ").append(getTexture());
        } else if (kd != null) {
            s.append(", kd = ").append(kd.format(number));
        }
        if (ks != null && p != null) {
            s.append(", ks = ").append(ks.format(number)).append(", p = ").append(number.apply(p));
        }
        return s.toString();
    }

    /**
     * Writes down how this shader shades {@code hit}, step by step, and returns the radiance, which
     * must be what {@link #shade} returns for a camera ray. A shader that does not say is shown by
     * its result alone.
     */
    public Vec3 explain(IntersectionRecord hit, Ray ray, ShadingSteps steps) {
        Vec3 result = shade(hit, ray, steps.context(), 0);
        steps.row("L", steps.vec(result) + "   (from its shade method; the trace knows no more of this shader)");
        return result;
    }

    /** The course conventions this shader shades by: 2017's unless it is one of 2019's ({@link ReflectionShader}). */
    public Course course() {
        return Course.Y2017;
    }

    /**
     * The shader a scene loaded under {@code course}'s conventions uses in this one's place, once its
     * properties are set: itself, unless the course shades it another way (a Lambertian or Phong under
     * 2019 becomes a {@link ReflectionShader} with that course's BRDF).
     */
    public Shader forCourse(Course course) {
        return this;
    }

    /**
     * Whether shading {@code hit} evaluates this shader's terms at all (its lights, texture and
     * highlight), for the render counters: true unless a rule makes the hit black first (2019's
     * back-face gate).
     */
    public boolean evaluatesAt(IntersectionRecord hit, Ray ray) {
        return true;
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
