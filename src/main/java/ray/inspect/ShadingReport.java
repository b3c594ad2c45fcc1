package ray.inspect;

import java.io.PrintWriter;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.DirectLighting;
import ray.shading.Glazed;
import ray.shading.Light;
import ray.shading.RGBNormals;
import ray.shading.Shader;
import ray.shading.Texture;

/**
 * How the hit's shader turns it into radiance, step by step: light by light for Lambertian and
 * Phong, the normal's color for RGBNormals, Schlick's R, the mirror ray and the substrate for
 * Glazed. Every total printed is what the shader itself returns.
 */
final class ShadingReport {
    private final Scene scene;
    private final SurfaceNames names;
    private final RecordedShading recorded;
    private final PrintWriter out;

    ShadingReport(Scene scene, SurfaceNames names, RecordedShading recorded, PrintWriter out) {
        this.scene = scene;
        this.names = names;
        this.recorded = recorded;
        this.out = out;
    }

    /** "Phong, kd = (…), ks = (…), p = 20". */
    static String describe(Shader shader) {
        if (shader == null) {
            return "none";
        }
        StringBuilder s = new StringBuilder(shader.getClass().getSimpleName());
        Vec3 kd = shader.getDiffuseColor();
        Vec3 ks = shader.getSpecularColor();
        Double p = shader.getExponent();
        Texture texture = shader.getTexture();
        if (texture != null) {
            s.append(", kd from ").append(texture);
        } else if (kd != null) {
            s.append(", kd = ").append(Fmt.vec(kd));
        }
        if (ks != null && p != null) {
            s.append(", ks = ").append(Fmt.vec(ks)).append(", p = ").append(Fmt.num(p));
        }
        if (shader instanceof Glazed) {
            Glazed g = (Glazed) shader;
            s.append(", refractive index ").append(Fmt.num(g.getRefractiveIndex())).append(", over ").append(describe(g.getSubstrate()));
        }
        return s.toString();
    }

    /** Prints the shading of {@code hit} seen along {@code ray}; returns the shader's result. */
    Vec3 explain(Shader shader, IntersectionRecord hit, Ray ray, String indent) {
        out.println(indent + "Shader " + describe(shader));
        String in = indent + "  ";
        if (shader instanceof Glazed) {
            return glazed((Glazed) shader, hit, ray, in);
        }
        if (shader instanceof RGBNormals) {
            out.println(Fmt.row(in, "L", "(n + 1)/2 = " + Fmt.vec(shader.shade(hit, ray, recorded, 0)) + "   (lights are not used)"));
            return shader.shade(hit, ray, recorded, 0);
        }
        if (shader instanceof DirectLighting) {
            return direct(shader, hit, ray, in);
        }
        Vec3 result = shader.shade(hit, ray, recorded, 0);
        out.println(Fmt.row(in, "L", Fmt.vec(result) + "   (from its shade method; the trace knows no more of this shader)"));
        return result;
    }

    private Vec3 direct(Shader shader, IntersectionRecord hit, Ray ray, String in) {
        out.println(in + (shader.getSpecularColor() != null && shader.getExponent() != null
                ? "L = Σ over lights of (kd ⊙ I · max(0, n·l) + ks ⊙ I · max(0, n·h)^p) / r²"
                : "L = Σ over lights of kd ⊙ I · max(0, n·l) / r²") + ", without the lights whose shadow ray is blocked");
        String notUnit = RecordChecks.notUnit(hit.normal);
        out.println(Fmt.row(in, "n", Fmt.vec(hit.normal) + (notUnit == null ? "   (the hit's unit normal)"
                : "   (the hit's normal, NOT unit length: |n| = " + Fmt.num(hit.normal.length()) + ")")));
        out.println(Fmt.row(in, "e", Fmt.vec(ray.direction.normalized().negate()) + "   (unit vector toward the eye)"));
        Texture texture = shader.getTexture();
        if (texture != null) {
            TextureReport.explain(texture, hit, in, out);
        }
        List<Light> lights = scene.getLights();
        if (lights.isEmpty()) {
            out.println(in + "The scene has no <light>, so the surface is black.");
        }
        LightReport report = new LightReport(scene, names, recorded, out);
        for (int k = 0; k < lights.size(); k++) {
            report.explain(k + 1, lights.get(k), shader, hit, ray, in);
        }
        Vec3 total = shader.shade(hit, ray, recorded, 0);
        out.println(Fmt.row(in, "L", Fmt.vec(total) + "   (the sum over the lights)"));
        return total;
    }

    private Vec3 glazed(Glazed glazed, IntersectionRecord hit, Ray ray, String in) {
        Vec3 e = ray.direction.normalized().negate();
        double cosTheta = hit.normal.dot(e);
        double r = glazed.reflectance(cosTheta);
        double n = glazed.getRefractiveIndex();
        double r0 = Math.pow((n - 1) / (n + 1), 2);
        out.println(in + "L = R · L_mirror + (1 − R) · L_substrate, R = R0 + (1 − R0)(1 − n·e)^5 (Schlick)");
        out.println(Fmt.row(in, "n, e", Fmt.vec(hit.normal) + ", " + Fmt.vec(e) + "   (normal; unit vector toward the eye)"));
        out.println(Fmt.row(in, "n·e", Fmt.num(cosTheta)));
        out.println(Fmt.row(in, "R", Fmt.num(r) + "   (R0 = ((n − 1)/(n + 1))² = " + Fmt.num(r0) + ")"));
        Vec3 lMirror = Vec3.ZERO;
        if (r != 0) {
            Vec3 mirror = hit.normal.times(2 * cosTheta).minus(e);
            Ray reflection = recorded.reflectionRay(hit, mirror);
            out.println(Fmt.row(in, "mirror", "2(n·e)n − e = " + Fmt.vec(mirror)));
            out.println(Fmt.row(in, "reflection", "ray from " + Fmt.vec(reflection.origin) + " (just off the surface)"));
            out.println(Fmt.row(in, "it hits", reflectionHit(reflection)));
            lMirror = recorded.radiance(reflection.copy(), 1);
            out.println(Fmt.row(in, "L_mirror", Fmt.vec(lMirror) + "   (the radiance it brings back, traced as the renderer does)"));
        }
        out.println(in + "The substrate, weighted by 1 − R = " + Fmt.num(1 - r) + ":");
        Vec3 substrate = explain(glazed.getSubstrate(), hit, ray, in + "  ");
        Vec3 total = glazed.shade(hit, ray, recorded, 0);
        out.println(Fmt.row(in, "L", "R · L_mirror + (1 − R) · L_substrate = " + Fmt.num(r) + " · " + Fmt.vec(lMirror)
                + " + " + Fmt.num(1 - r) + " · " + Fmt.vec(substrate) + " = " + Fmt.vec(total)));
        return total;
    }

    private String reflectionHit(Ray reflection) {
        IntersectionRecord hit = new IntersectionRecord();
        if (!scene.getSurfaces().intersect(hit, reflection.copy())) {
            return "nothing: it sees the background " + Fmt.vec(scene.getBackColor());
        }
        List<ProbeNode> roots = ProbeTree.of(scene.getSurfaces(), reflection);
        ProbeNode node = ProbeTree.bySurface(ProbeTree.primitives(roots), hit.surface);
        String what = node != null ? ProbeTree.path(roots, node, names) : String.valueOf(hit.surface);
        return what + " at t = " + Fmt.num(hit.t) + ", at " + Fmt.vec(hit.location) + " (shader "
                + describe(hit.surface.getShader()) + ")";
    }
}
