package ray.inspect;

import java.io.PrintWriter;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Light;
import ray.shading.Shader;
import ray.shading.ShadingContext;
import ray.shading.ShadingSteps;
import ray.shading.Texture;

/**
 * How the hit's shader turns it into radiance, step by step. Each shader writes its own formula
 * ({@link Shader#explain}); this report prints it and supplies the shared steps: the lights one by
 * one for a lit shader, the mirror ray a glaze traces, a substrate explained in turn. Every total
 * printed is what the shader itself returns.
 */
final class ShadingReport {
    private final Scene scene;
    private final SurfaceNames names;
    private final RecordedShading recorded;
    private final PrintWriter out;
    private final LightReport lightReport;

    ShadingReport(Scene scene, SurfaceNames names, RecordedShading recorded, PrintWriter out) {
        this.scene = scene;
        this.names = names;
        this.recorded = recorded;
        this.out = out;
        this.lightReport = new LightReport(scene, names, recorded, out);
    }

    /** "Phong, kd = (…), ks = (…), p = 20", or "none". */
    static String describe(Shader shader) {
        return shader == null ? "none" : shader.describe(Fmt::num);
    }

    /** Prints the shading of {@code hit} seen along {@code ray}; returns the shader's result. */
    Vec3 explain(Shader shader, IntersectionRecord hit, Ray ray, String indent) {
        out.println(indent + "Shader " + describe(shader));
        return shader.explain(hit, ray, new Steps(indent + "  "));
    }

    /** The steps every shader may take, printed at one indent. */
    private final class Steps implements ShadingSteps {
        private final String in;

        Steps(String in) {
            this.in = in;
        }

        @Override
        public void line(String text) {
            out.println(in + text);
        }

        @Override
        public void row(String label, String text) {
            out.println(Fmt.row(in, label, text));
        }

        @Override
        public String num(double x) {
            return Fmt.num(x);
        }

        @Override
        public ShadingContext context() {
            return recorded;
        }

        @Override
        public Vec3 lightByLight(Shader shader, IntersectionRecord hit, Ray ray) {
            String notUnit = RecordChecks.notUnit(hit.normal);
            row("n", Fmt.vec(hit.normal) + (notUnit == null ? "   (the hit's unit normal)"
                    : "   (the hit's normal, NOT unit length: |n| = " + Fmt.num(hit.normal.length()) + ")"));
            row("e", Fmt.vec(ray.direction.normalized().negate()) + "   (unit vector toward the eye)");
            Texture texture = shader.getTexture();
            if (texture != null) {
                TextureReport.explain(texture, hit, in, out);
            }
            List<Light> lights = scene.getLights();
            if (lights.isEmpty()) {
                line("The scene has no <light>, so the surface is black.");
            }
            for (int k = 0; k < lights.size(); k++) {
                lightReport.explain(k + 1, lights.get(k), shader, hit, ray, in);
            }
            Vec3 total = shader.shade(hit, ray, recorded, 0);
            row("L", Fmt.vec(total) + "   (the sum over the lights)");
            return total;
        }

        @Override
        public Vec3 mirror(IntersectionRecord hit, Vec3 direction) {
            Ray reflection = recorded.reflectionRay(hit, direction);
            row("mirror", "2(n·e)n − e = " + Fmt.vec(direction));
            row("reflection", "ray from " + Fmt.vec(reflection.origin) + " (just off the surface)");
            row("it hits", reflectionHit(reflection));
            Vec3 radiance = recorded.radiance(reflection.copy(), 1);
            row("L_mirror", Fmt.vec(radiance) + "   (the radiance it brings back, traced as the renderer does)");
            return radiance;
        }

        @Override
        public Vec3 part(Shader part, IntersectionRecord hit, Ray ray) {
            return explain(part, hit, ray, in + "  ");
        }
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
