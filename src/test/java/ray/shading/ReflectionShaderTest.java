package ray.shading;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Checks ReflectionShader.shade, the course's 2019 shader, on points lit by hand-placed lights, each
 * value worked out in its comment (or given by the course's own tests): L = Σ over the lights that
 * reach the point of f(l, v) ⊙ I · max(0, n·l) / r², black when n·v ≤ 0, plus, when k_m ≠ 0,
 * R ⊙ L_mirror with Schlick's R = k_m + (1 − k_m)(1 − n·v)^5 and the mirror ray one depth deeper.
 */
@Points(1)
public class ReflectionShaderTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final Vec3 NO_MIRROR = Vec3.ZERO;

    private static ReflectionShader shader(Brdf brdf, Vec3 rhoD, Vec3 km) {
        return new ReflectionShader("test", brdf, rhoD, null, km, null, null);
    }

    /** The course's point: (0, 1, 0) with normal +y, seen from (0, 2, 0), ρd = (0, 0.5, 0.5). */
    private static LitPoint coursePoint() {
        return new LitPoint(v(0, 1, 0), v(0, 1, 0), v(0, 2, 0));
    }

    /** The course's check: a light at (5, 5, 5) of intensity 100 gives ρd/π · 100 · (4/√66)/66 = (0, 0.37300451811919, 0.37300451811919)/π. */
    @Test
    @Points(2)
    public void theCoursesLambertianPoint() {
        LitPoint p = coursePoint().light(v(5, 5, 5), v(100, 100, 100));
        double g = 0.37300451811919 / Math.PI;
        p.check(shader(new LambertianBrdf(), v(0, 0.5, 0.5), NO_MIRROR), v(0, g, g), "f ⊙ I · (n·l)/r² with f = ρd/π, n·l = 4/√66, r² = 66");
    }

    /**
     * The course's three lights: (5, 5, 5) of intensity 100 and twice (0, 5, 0) of intensity (0, 30, 50),
     * which adds ρd/π · (0, 30, 50)/16 each time: (0, 2.24800451811919, 3.49800451811919)/π; with the first
     * blocked, (0, 1.875, 3.125)/π.
     */
    @Test
    @Points(2)
    public void theCoursesThreeLightsOneBlocked() {
        ReflectionShader matte = shader(new LambertianBrdf(), v(0, 0.5, 0.5), NO_MIRROR);
        LitPoint all = coursePoint().light(v(5, 5, 5), v(100, 100, 100)).light(v(0, 5, 0), v(0, 30, 50)).light(v(0, 5, 0), v(0, 30, 50));
        all.check(matte, v(0, 2.24800451811919 / Math.PI, 3.49800451811919 / Math.PI), "the three lights' shares added");
        LitPoint blocked = coursePoint().blockedLight(v(5, 5, 5), v(100, 100, 100)).light(v(0, 5, 0), v(0, 30, 50))
                .light(v(0, 5, 0), v(0, 30, 50));
        blocked.check(matte, v(0, 1.875 / Math.PI, 3.125 / Math.PI), "only the two lights the shadow test lets through");
    }

    /**
     * The course's Phong checks (ks = 1, p = 1): lights at (−1, 5, 2) of intensity 100 and twice at
     * (1, 5, 1) of intensity (0, 30, 50) give (4.022259, 8.2814045, 10.679813); with the last two
     * blocked, (4.022259, 4.6837916, 4.6837916), to the course's seven or eight digits.
     */
    @Test
    @Points(2)
    public void theCoursesPhongPoints() {
        ReflectionShader shiny = shader(new PhongBrdf(v(1, 1, 1), 1), v(0, 0.5, 0.5), NO_MIRROR);
        LitPoint all = coursePoint().light(v(-1, 5, 2), v(100, 100, 100)).light(v(1, 5, 1), v(0, 30, 50)).light(v(1, 5, 1), v(0, 30, 50));
        assertVec("ReflectionShader.shade at " + all.describe(), v(4.022259, 8.2814045, 10.679813), all.shade(shiny), 1e-6);
        LitPoint blocked = coursePoint().light(v(-1, 5, 2), v(100, 100, 100)).blockedLight(v(1, 5, 1), v(0, 30, 50))
                .blockedLight(v(1, 5, 1), v(0, 30, 50));
        assertVec("ReflectionShader.shade at " + blocked.describe(), v(4.022259, 4.6837916, 4.6837916), blocked.shade(shiny), 1e-6);
    }

    /**
     * Seen from behind its normal (n·v < 0), the surface is black, though a light shines on its front
     * and it is a mirror. From the front (eye at (0, 1, 3): n·v = 3/√10) the same shader gives the
     * light's 1/π · 10 · 1/4 plus Schlick's 0.5 + 0.5(1 − 3/√10)^5 times the mirror's 1.
     */
    @Test
    @Points(2)
    public void seenFromBehindIsBlack() {
        ReflectionShader mirror = shader(new LambertianBrdf(), v(1, 1, 1), v(0.5, 0.5, 0.5));
        LitPoint front = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 1, 3)).light(v(0, 0, 2), v(10, 10, 10)).mirrorSees(v(1, 1, 1));
        double expected = 10 / (4 * Math.PI) + 0.5 + 0.5 * Math.pow(1 - 3 / Math.sqrt(10), 5);
        front.check(mirror, v(expected, expected, expected), "seen from the front: the light and the mirror");
        LitPoint behind = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 1, -3)).light(v(0, 0, 2), v(10, 10, 10)).mirrorSees(v(1, 1, 1));
        behind.check(mirror, Vec3.ZERO, "n·v < 0: no light and no mirror term");
        assertEquals("mirror rays asked from behind", 0, behind.mirrorDirections.size());
    }

    /** A light behind the surface (n·l < 0) adds nothing, never a negative amount; one straight above at distance 1, I = π, adds ρd. */
    @Test
    public void aLightBehindTheSurfaceAddsNothing() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 3)).light(v(1, 0, -2), v(50, 50, 50))
                .light(v(0, 0, 1), v(Math.PI, Math.PI, Math.PI));
        p.check(shader(new LambertianBrdf(), v(0.5, 0.25, 1), NO_MIRROR), v(0.5, 0.25, 1), "max(0, n·l) = 0 for the light behind");
    }

    /** A texture's color at the hit replaces ρd: a white shader with a (0.2, 0.4, 0.6) texture under a light straight above at distance 1, I = π. */
    @Test
    public void aTexturesColorIsTheDiffuseReflectance() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 3)).light(v(0, 0, 1), v(Math.PI, Math.PI, Math.PI));
        ReflectionShader textured = new ReflectionShader("test", new LambertianBrdf(), v(1, 1, 1), new OneColor(v(0.2, 0.4, 0.6)), NO_MIRROR,
                null, null);
        p.check(textured, v(0.2, 0.4, 0.6), "diffuseColorAt(hit)/π · π · 1 / 1");
    }

    /**
     * Head on (n·v = 1), Schlick's weight is k_m itself: no lights, k_m = (0.2, 0.4, 0.6), and the mirror
     * direction, straight back up, brings back (1, 2, 3): L = (0.2, 0.8, 1.8), asked one depth deeper.
     */
    @Test
    @Points(2)
    public void headOnTheMirrorWeighsKm() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 5)).mirrorSees(v(1, 2, 3));
        p.check(shader(new LambertianBrdf(), v(1, 1, 1), v(0.2, 0.4, 0.6)), v(0.2, 0.8, 1.8), "R = k_m at n·v = 1");
        assertEquals("mirror rays asked", 1, p.mirrorDirections.size());
        assertVec("the mirror direction (the ray reflected about n)", v(0, 0, 1), p.mirrorDirections.get(0).normalized(), 1e-12);
        assertEquals("the mirror ray's depth", 1, (int) p.mirrorDepths.get(0));
    }

    /**
     * At 60° from the normal, n·v = ½ and (1 − n·v)^5 = 1/32: with k_m = 0.04, R = 0.04 + 0.96/32 = 0.07.
     * The ray comes down along (√3/2, 0, −½) and leaves along (√3/2, 0, ½); at depth 3 it asks depth 4.
     */
    @Test
    @Points(2)
    public void schlicksWeightAtSixtyDegrees() {
        double s = Math.sqrt(3) / 2;
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(-2 * s, 0, 1)).mirrorSees(v(1, 1, 1));
        ReflectionShader mirror = shader(new LambertianBrdf(), v(1, 1, 1), v(0.04, 0.04, 0.04));
        assertVec("ReflectionShader.shade at " + p.describe() + ", k_m = 0.04, the mirror seeing (1, 1, 1)", v(0.07, 0.07, 0.07),
                p.shade(mirror, 3), 1e-12);
        assertVec("the mirror direction (the ray reflected about n)", v(s, 0, 0.5), p.mirrorDirections.get(0).normalized(), 1e-12);
        assertEquals("the mirror ray's depth", 4, (int) p.mirrorDepths.get(0));
    }

    /** k_m = 0 in every channel: no mirror term and no mirror ray (the case's context says so if one is asked). */
    @Test
    public void noMirrorCoefficientTracesNoMirrorRay() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(3, 0, 1)).light(v(0, 0, 2), v(4, 4, 4));
        p.check(shader(new LambertianBrdf(), v(0.5, 0.5, 0.5), NO_MIRROR), v(0.5 / Math.PI, 0.5 / Math.PI, 0.5 / Math.PI),
                "ρd/π · 4 · 1/4, and no mirror ray");
    }

    /** Lights and mirror together: a light straight above at distance 1, I = π, ρd = 0.5, and a head-on mirror k_m = 0.5 seeing 1: L = 0.5 + 0.5. */
    @Test
    public void lightsAndMirrorAddUp() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 4)).light(v(0, 0, 1), v(Math.PI, Math.PI, Math.PI)).mirrorSees(v(1, 1, 1));
        p.check(shader(new LambertianBrdf(), v(0.5, 0.5, 0.5), v(0.5, 0.5, 0.5)), v(1, 1, 1), "0.5/π · π + 0.5 · 1");
    }
}
