package ray.inspect;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Course;
import ray.shading.Light;
import ray.shading.Shader;

/**
 * One light's part of a direct-lighting shader's result at a hit, as numbers: l, r², n·l, the
 * shadow ray, the terms of the formula (Lambertian kd ⊙ I · max(0, n·l)/r², Phong's specular
 * ks ⊙ I · max(0, n·h)^p/r² with h = normalize(l + e); under 2019's conventions kd/π and the
 * specular term times max(0, n·l); a microfacet BRDF's factors, {@link MicrofacetTerms}), and what
 * the shader itself adds for the light. {@link LightReport} prints them for {@code ray1 trace}; {@link PixelStory} sends them to
 * {@code ray1 explore}'s page.
 */
final class LightFacts {
    final Light light;
    /** Unit vector from the hit to the light. */
    final Vec3 l;
    /** Squared distance from the hit to the light. */
    final double r2;
    final double nl;
    /** The shadow ray and its blockers, or null when the light adds nothing here even unshadowed (no ray is traced). */
    final ShadowCheck shadow;
    /** kd ⊙ I · max(0, n·l) / r², or null when the shader has no diffuse color. */
    final Vec3 diffuse;
    /** The kd the diffuse term used (a texture's color at the hit, or the shader's), or null. */
    final Vec3 kd;
    /** Phong's half vector h, n·h, and ks ⊙ I · max(0, n·h)^p / r²; null when the shader has no specular term. */
    final Vec3 h;
    final Double nh;
    final Vec3 specular;
    final Vec3 ks;
    final Double exponent;
    /** The microfacet BRDF's factors and the facets' share, or null for a shader without that BRDF. */
    final MicrofacetTerms microfacet;
    /** What the shader itself returns for this light alone, with its shadow: zero when the shadow ray is blocked. */
    final Vec3 adds;

    private LightFacts(Light light, Vec3 l, double r2, double nl, ShadowCheck shadow, Vec3 kd, Vec3 diffuse, Vec3 ks,
            Double exponent, Vec3 h, Double nh, Vec3 specular, MicrofacetTerms microfacet, Vec3 adds) {
        this.light = light;
        this.l = l;
        this.r2 = r2;
        this.nl = nl;
        this.shadow = shadow;
        this.kd = kd;
        this.diffuse = diffuse;
        this.ks = ks;
        this.exponent = exponent;
        this.h = h;
        this.nh = nh;
        this.specular = specular;
        this.microfacet = microfacet;
        this.adds = adds;
    }

    /** The light's part at {@code hit} seen along {@code ray}, with the renderer's own shadow rays. */
    static LightFacts of(Scene scene, RecordedShading recorded, Light light, Shader shader, IntersectionRecord hit, Ray ray) {
        Vec3 toLight = light.getPosition().minus(hit.location);
        double r2 = toLight.lengthSquared();
        Vec3 l = toLight.normalized();
        double nl = hit.normal.dot(l);
        Vec3 intensity = light.getIntensity();
        Vec3 unshadowed = shader.shade(hit, ray, recorded.onlyLight(light, true), 0);
        ShadowCheck shadow = isZero(unshadowed) ? null : ShadowCheck.of(scene, recorded, hit, light.getPosition());
        Vec3 kd = shader.diffuseColorAt(hit);
        // 2019's BRDFs divide ρd by π and weight the highlight by n·l too (Course).
        boolean y2019 = shader.course() == Course.Y2019;
        double diffuseScale = y2019 ? 1 / Math.PI : 1;
        Vec3 diffuse = kd == null ? null : kd.times(intensity).times(diffuseScale * Math.max(0, nl) / r2);
        Vec3 ks = shader.getSpecularColor();
        Double p = shader.getExponent();
        Vec3 h = null;
        Double nh = null;
        Vec3 specular = null;
        if (ks != null && p != null) {
            Vec3 e = ray.direction.normalized().negate();
            h = l.plus(e).normalized();
            nh = hit.normal.dot(h);
            specular = ks.times(intensity).times(Math.pow(Math.max(0, nh), p) * (y2019 ? Math.max(0, nl) : 1) / r2);
        }
        MicrofacetTerms microfacet = MicrofacetTerms.of(shader, hit.normal, l, ray.direction.normalized().negate(), intensity, r2);
        if (microfacet != null) {
            specular = microfacet.specular;
        }
        boolean blocked = shadow != null && shadow.blockedByGroup;
        Vec3 adds = blocked ? Vec3.ZERO : shader.shade(hit, ray, recorded.onlyLight(light, false), 0);
        return new LightFacts(light, l, r2, nl, shadow, kd, diffuse, ks, p, h, nh, specular, microfacet, adds);
    }

    boolean blocked() {
        return shadow != null && shadow.blockedByGroup;
    }

    /**
     * What the formula says the light adds (zero when blocked, else the diffuse and specular terms
     * worked out here), or null for a shader with neither term (nothing to compare with).
     */
    Vec3 formula() {
        if (diffuse == null && specular == null) {
            return null;
        }
        if (blocked()) {
            return Vec3.ZERO;
        }
        Vec3 sum = Vec3.ZERO;
        if (diffuse != null) {
            sum = sum.plus(diffuse);
        }
        if (specular != null) {
            sum = sum.plus(specular);
        }
        return sum;
    }

    /** Whether the shader's own result for the light is the formula's, to a millionth of it (a light loop of the students' may not be). */
    boolean agreesWithFormula() {
        Vec3 expected = formula();
        if (expected == null) {
            return true;
        }
        if (adds == null) {
            return false;
        }
        for (int axis = 0; axis < 3; axis++) {
            double e = expected.get(axis);
            if (!(Math.abs(adds.get(axis) - e) <= 1e-6 * Math.max(1e-3, Math.abs(e)))) {
                return false;
            }
        }
        return true;
    }

    private static boolean isZero(Vec3 v) {
        return v.x == 0 && v.y == 0 && v.z == 0;
    }
}
