package ray.inspect;

import java.io.PrintWriter;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Course;
import ray.shading.Light;
import ray.shading.Shader;

/** Prints one light's part of a direct-lighting shader's result at a hit ({@link LightFacts}) with the numbers of each term. */
final class LightReport {
    private final Scene scene;
    private final SurfaceNames names;
    private final RecordedShading recorded;
    private final PrintWriter out;

    LightReport(Scene scene, SurfaceNames names, RecordedShading recorded, PrintWriter out) {
        this.scene = scene;
        this.names = names;
        this.recorded = recorded;
        this.out = out;
    }

    /** Prints the light's part and returns what the shader adds for it. */
    Vec3 explain(int number, Light light, Shader shader, IntersectionRecord hit, Ray ray, String indent) {
        LightFacts f = LightFacts.of(scene, recorded, light, shader, hit, ray);
        Vec3 intensity = light.getIntensity();
        out.println(indent + "Light " + number + " at " + Fmt.vec(light.getPosition()) + ", intensity I = " + Fmt.vec(intensity));
        String in = indent + "  ";
        out.println(Fmt.row(in, "l", Fmt.vec(f.l) + "   (unit vector from the hit to the light)"));
        out.println(Fmt.row(in, "r", Fmt.num(Math.sqrt(f.r2)) + "   (r² = " + Fmt.num(f.r2) + ")"));
        out.println(Fmt.row(in, "n·l", Fmt.num(f.nl) + (f.nl <= 0 ? "   (≤ 0: the light is behind the surface)" : "")));
        if (f.shadow == null) {
            out.println(Fmt.row(in, "shadow", "no shadow ray: this light adds nothing here anyway"));
        } else {
            f.shadow.print(names, in, out);
        }
        boolean y2019 = shader.course() == Course.Y2019;
        if (f.diffuse != null) {
            out.println(Fmt.row(in, "diffuse", (y2019 ? "kd/π" : "kd") + " ⊙ I · max(0, n·l) / r² = " + Fmt.vec(f.kd)
                    + (y2019 ? "/π" : "") + " ⊙ " + Fmt.vec(intensity)
                    + " · " + Fmt.num(Math.max(0, f.nl)) + " / " + Fmt.num(f.r2) + " = " + Fmt.vec(f.diffuse)));
        }
        if (f.specular != null && f.microfacet == null) {
            out.println(Fmt.row(in, "h", Fmt.vec(f.h) + "   (normalize(l + e), the half vector)"));
            out.println(Fmt.row(in, "n·h", Fmt.num(f.nh)));
            out.println(Fmt.row(in, "specular", (y2019 ? "ks ⊙ I · max(0, n·h)^p · max(0, n·l) / r² = " : "ks ⊙ I · max(0, n·h)^p / r² = ")
                    + Fmt.vec(f.ks) + " ⊙ " + Fmt.vec(intensity) + " · " + Fmt.num(Math.max(0, f.nh)) + "^" + Fmt.num(f.exponent)
                    + (y2019 ? " · " + Fmt.num(Math.max(0, f.nl)) : "") + " / " + Fmt.num(f.r2) + " = "
                    + Fmt.vec(f.specular) + (y2019 ? "   (2019: weighted by n·l like the diffuse term)" : "   (not gated by n·l)")));
        }
        if (f.microfacet != null) {
            printMicrofacet(f.microfacet, intensity, f, in);
        }
        if (f.agreesWithFormula() || !shader.evaluatesAt(hit, ray)) {
            out.println(Fmt.row(in, "adds", f.blocked() ? "nothing: the shadow ray is blocked" : Fmt.vec(f.adds)));
        } else {
            out.println(Fmt.row(in, "adds", Fmt.vec(f.adds) + "   ✗ not the formula's " + Fmt.vec(f.formula())
                    + ": the shader's shade returns another value for this light"));
        }
        return f.adds;
    }

    /** The microfacet BRDF's factors, each as the shader's own classes compute it, and the facets' share. */
    private void printMicrofacet(MicrofacetTerms m, Vec3 intensity, LightFacts f, String in) {
        out.println(Fmt.row(in, "h", Fmt.vec(m.h) + "   (normalize(l + e), the half vector)"));
        if (m.error != null) {
            out.println(Fmt.row(in, "facets", "✗ " + m.error));
            return;
        }
        out.println(Fmt.row(in, "F", Fmt.num(m.fresnel) + "   (Fresnel.reflectance(|l·h| = " + Fmt.num(m.lh) + "), nt = " + Fmt.num(m.nt) + ")"));
        out.println(Fmt.row(in, "D", Fmt.num(m.distribution) + "   (" + m.distributionClass + ".normalDistribution(n, h), α = "
                + Fmt.num(m.alpha) + ")"));
        out.println(Fmt.row(in, "G1(l)", Fmt.num(m.maskingL) + "   (" + m.distributionClass + ".masking(l, n, h))"));
        out.println(Fmt.row(in, "G1(v)", Fmt.num(m.maskingV) + "   (" + m.distributionClass + ".masking(e, n, h))"));
        out.println(Fmt.row(in, "facets", "k_mf ⊙ I · F·D·G1(l)·G1(v) / (4 n·l n·v) · n·l / r² = " + Fmt.vec(f.ks) + " ⊙ "
                + Fmt.vec(intensity) + " · " + Fmt.num(m.fresnel) + "·" + Fmt.num(m.distribution) + "·" + Fmt.num(m.maskingL) + "·"
                + Fmt.num(m.maskingV) + " / (4 · " + Fmt.num(f.nl) + " · " + Fmt.num(m.nv) + ") · " + Fmt.num(Math.max(0, f.nl)) + " / " + Fmt.num(f.r2)
                + " = " + Fmt.vec(m.specular)));
    }
}
