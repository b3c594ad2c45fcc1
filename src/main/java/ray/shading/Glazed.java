package ray.shading;

import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.function.DoubleFunction;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * A glaze over a substrate: a mirror reflection weighted by Schlick's Fresnel approximation,
 * L = R·L_mirror + (1 − R)·L_substrate, with R = R0 + (1 − R0)(1 − cos θ)^5 and
 * R0 = ((n − 1)/(n + 1))² (Schlick, "An Inexpensive BRDF Model for Physically-based Rendering", 1994).
 */
public class Glazed extends Shader {
    /** Reflection rays stop after this many bounces; the last one reflects black. */
    public static final int MAX_DEPTH = 12;

    private double refractiveIndex = 1.5;
    private Shader substrate = new Lambertian();

    public void setRefractiveIndex(double refractiveIndex) {
        this.refractiveIndex = ray.math.PositiveNumber.require("refractiveIndex", refractiveIndex);
    }

    public double getRefractiveIndex() {
        return refractiveIndex;
    }

    public void setSubstrate(Shader substrate) {
        this.substrate = substrate;
    }

    public Shader getSubstrate() {
        return substrate;
    }

    /** A glaze is ray1's own under either course; its substrate is shaded by the course's rules (its default too). */
    @Override
    public Shader forCourse(Course course) {
        substrate = substrate.forCourse(course);
        return this;
    }

    @Override
    public Set<Effect> effects() {
        return EnumSet.of(Effect.REFLECTION);
    }

    @Override
    public List<Shader> parts() {
        return List.of(substrate);
    }

    /** Schlick's reflectance for the cosine of the angle between the normal and the eye direction. */
    public double reflectance(double cosTheta) {
        double r0 = (refractiveIndex - 1) / (refractiveIndex + 1);
        r0 *= r0;
        double m = 1 - Math.min(1, Math.abs(cosTheta));
        return r0 + (1 - r0) * m * m * m * m * m;
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        Vec3 toEye = towardEye(ray);
        double cosTheta = hit.normal.dot(toEye);
        double r = reflectance(cosTheta);
        Vec3 base = substrate.shade(hit, ray, context, depth).times(1 - r);
        // At the depth cap the glaze reflects black; a zero reflectance needs no ray.
        if (depth + 1 > MAX_DEPTH || r == 0) {
            return base;
        }
        return base.plus(context.radiance(hit, mirror(hit.normal, toEye, cosTheta), depth + 1).times(r));
    }

    /** The eye direction e reflected about the normal n: 2(n·e)n − e, given n·e. */
    private static Vec3 mirror(Vec3 normal, Vec3 toEye, double cosTheta) {
        return normal.times(2 * cosTheta).minus(toEye);
    }

    @Override
    public String describe(DoubleFunction<String> number) {
        return super.describe(number) + ", refractive index " + number.apply(refractiveIndex)
                + ", over " + (substrate == null ? "none" : substrate.describe(number));
    }

    @Override
    public Vec3 explain(IntersectionRecord hit, Ray ray, ShadingSteps steps) {
        Vec3 e = towardEye(ray);
        double cosTheta = hit.normal.dot(e);
        double r = reflectance(cosTheta);
        steps.line("L = R · L_mirror + (1 − R) · L_substrate, R = R0 + (1 − R0)(1 − n·e)^5 (Schlick)");
        steps.row("n, e", steps.vec(hit.normal) + ", " + steps.vec(e) + "   (normal; unit vector toward the eye)");
        steps.row("n·e", steps.num(cosTheta));
        // Head on (cos θ = 1) Schlick's R is R0 itself.
        steps.row("R", steps.num(r) + "   (R0 = ((n − 1)/(n + 1))² = " + steps.num(reflectance(1)) + ")");
        Vec3 lMirror = r == 0 ? Vec3.ZERO : steps.mirror(hit, mirror(hit.normal, e, cosTheta));
        steps.line("The substrate, weighted by 1 − R = " + steps.num(1 - r) + ":");
        Vec3 lSubstrate = steps.part(substrate, hit, ray);
        Vec3 total = shade(hit, ray, steps.context(), 0);
        steps.row("L", "R · L_mirror + (1 − R) · L_substrate = " + steps.num(r) + " · " + steps.vec(lMirror)
                + " + " + steps.num(1 - r) + " · " + steps.vec(lSubstrate) + " = " + steps.vec(total));
        return total;
    }
}
