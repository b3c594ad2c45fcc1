package ray.trace;

import java.io.PrintWriter;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.shading.Phong;
import ray.shading.Shader;

/**
 * One light's part of a direct-lighting shader's result at a hit: l, r, n·l, the shadow ray, the
 * terms of the formula with their numbers (Lambertian kd ⊙ I · max(0, n·l)/r², Phong's specular
 * ks ⊙ I · max(0, n·h)^p/r² with h = normalize(l + e)), and what the shader itself adds for it.
 */
final class LightReport {
    private final Scene scene;
    private final SurfaceNames names;
    private final TraceTracer tracer;
    private final PrintWriter out;

    LightReport(Scene scene, SurfaceNames names, TraceTracer tracer, PrintWriter out) {
        this.scene = scene;
        this.names = names;
        this.tracer = tracer;
        this.out = out;
    }

    /** Prints the light's part and returns what the shader adds for it. */
    Vec3 explain(int number, Light light, Shader shader, IntersectionRecord hit, Ray ray, String indent) {
        Vec3 toLight = light.getPosition().minus(hit.location);
        double r2 = toLight.lengthSquared();
        Vec3 l = toLight.normalized();
        double nl = hit.normal.dot(l);
        Vec3 intensity = light.getIntensity();
        out.println(indent + "Light " + number + " at " + Fmt.vec(light.getPosition()) + ", intensity I = " + Fmt.vec(intensity));
        String in = indent + "  ";
        out.println(Fmt.row(in, "l", Fmt.vec(l) + "   (unit vector from the hit to the light)"));
        out.println(Fmt.row(in, "r", Fmt.num(Math.sqrt(r2)) + "   (r² = " + Fmt.num(r2) + ")"));
        out.println(Fmt.row(in, "n·l", Fmt.num(nl) + (nl <= 0 ? "   (≤ 0: the light is behind the surface)" : "")));
        Vec3 unshadowed = shader.shade(hit, ray, tracer.onlyLight(light, true), 0);
        boolean blocked = false;
        if (isZero(unshadowed)) {
            out.println(Fmt.row(in, "shadow", "no shadow ray: this light adds nothing here anyway"));
        } else {
            blocked = ShadowCheck.print(scene, names, tracer, hit, light.getPosition(), in, out);
        }
        terms(shader, hit, ray, l, nl, r2, intensity, in);
        Vec3 adds = blocked ? Vec3.ZERO : shader.shade(hit, ray, tracer.onlyLight(light, false), 0);
        out.println(Fmt.row(in, "adds", blocked ? "nothing: the shadow ray is blocked" : Fmt.vec(adds)));
        return adds;
    }

    private void terms(Shader shader, IntersectionRecord hit, Ray ray, Vec3 l, double nl, double r2, Vec3 intensity, String in) {
        Vec3 kd = ShaderParameters.diffuseColorAt(shader, hit);
        if (kd != null) {
            Vec3 diffuse = kd.times(intensity).times(Math.max(0, nl) / r2);
            out.println(Fmt.row(in, "diffuse", "kd ⊙ I · max(0, n·l) / r² = " + Fmt.vec(kd) + " ⊙ " + Fmt.vec(intensity)
                    + " · " + Fmt.num(Math.max(0, nl)) + " / " + Fmt.num(r2) + " = " + Fmt.vec(diffuse)));
        }
        Vec3 ks = ShaderParameters.specularColor(shader);
        Double p = ShaderParameters.exponent(shader);
        if (ks != null && p != null) {
            Vec3 e = ray.direction.normalized().negate();
            Vec3 h = l.plus(e).normalized();
            double nh = hit.normal.dot(h);
            double power = Math.pow(Math.max(0, nh), p);
            out.println(Fmt.row(in, "h", Fmt.vec(h) + "   (normalize(l + e), the half vector)"));
            out.println(Fmt.row(in, "n·h", Fmt.num(nh)));
            out.println(Fmt.row(in, "specular", "ks ⊙ I · max(0, n·h)^p / r² = " + Fmt.vec(ks) + " ⊙ " + Fmt.vec(intensity)
                    + " · " + Fmt.num(Math.max(0, nh)) + "^" + Fmt.num(p) + " / " + Fmt.num(r2) + " = "
                    + Fmt.vec(ks.times(intensity).times(power / r2)) + "   (not gated by n·l)"));
        }
    }

    private static boolean isZero(Vec3 v) {
        return v.x == 0 && v.y == 0 && v.z == 0;
    }
}
