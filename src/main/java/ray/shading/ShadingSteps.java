package ray.shading;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Where a shader writes down how it shades one hit, for {@code ray1 trace}: each shader explains
 * its own formula ({@link Shader#explain}), and the inspection code supplies the steps that are the
 * same for every shader (the lights one by one, a mirror ray traced, a part shader explained in
 * turn). A shader that explains nothing is shown by its result.
 */
public interface ShadingSteps {
    /** A line of its own, such as the formula. */
    void line(String text);

    /** A labelled value, "R   0.04   (R0 = …)". */
    void row(String label, String text);

    /** A number as the trace writes it (rounded to what tells values apart). */
    String num(double x);

    /** A vector as the trace writes it. */
    default String vec(Vec3 v) {
        return v == null ? "null" : v.format(this::num);
    }

    /** What the shader shades with: the scene's lights, its shadow and mirror rays, as the renderer traces them. */
    ShadingContext context();

    /**
     * Explains a shader that sums over point lights, light by light (the normal, the eye, kd and each
     * light's share and shadow ray), and returns its total.
     */
    Vec3 lightByLight(Shader shader, IntersectionRecord hit, Ray ray);

    /** Traces the mirror ray leaving {@code hit} along {@code direction}, says what it hits, and returns the radiance it brings back. */
    Vec3 mirror(IntersectionRecord hit, Vec3 direction);

    /** Explains {@code part}, a shader this one shades with, one level in, and returns its result. */
    Vec3 part(Shader part, IntersectionRecord hit, Ray ray);
}
