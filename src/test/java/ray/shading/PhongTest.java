package ray.shading;

import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Checks Phong.shade on points lit by hand-placed lights, each value worked out in its comment:
 * L = Σ over the lights that reach the point of (kd · max(0, n·l) + ks · max(0, n·h)^p) ⊙ I / r²,
 * with h = normalize(l + e) and e the unit vector toward the eye. The exponents are whole numbers, as
 * in every scene, so that Math.pow and a loop of products are equally right.
 */
@Points(1)
public class PhongTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static Phong shiny(Vec3 kd, Vec3 ks, double p) {
        Phong shader = new Phong();
        shader.setDiffuseColor(kd);
        shader.setSpecularColor(ks);
        shader.setExponent(p);
        shader.complete();
        return shader;
    }

    /** Light and eye straight above: l = e = h = n, so both factors are 1 and L = (kd + ks) ⊙ I / r². */
    @Test
    @Points(2)
    public void lightAndEyeStraightAbove() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 4)).light(v(0, 0, 2), v(4, 8, 4));
        p.check(shiny(v(0.5, 0.25, 1), v(1, 1, 1), 10), v(1.5, 2.5, 2), "(kd + ks) ⊙ I / r² = (1.5, 1.25, 2) ⊙ (4, 8, 4) / 4");
    }

    /**
     * Eye straight above, light at (3, 0, 4): l = (0.6, 0, 0.8), h = normalize(0.6, 0, 1.8), n·h = 3/√10,
     * so with p = 2 the highlight is (n·h)² = 0.9 and the diffuse factor 0.8; I/r² = 1.
     */
    @Test
    @Points(2)
    public void theHighlightUsesTheHalfVector() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 7)).light(v(3, 0, 4), v(25, 25, 25));
        p.check(shiny(v(0.5, 0.5, 0.5), v(1, 0.5, 0.25), 2), v(0.4 + 0.9, 0.4 + 0.45, 0.4 + 0.225),
                "kd · 0.8 + ks · (n·h)², with n·h = 3/√10 from h = normalize(l + e)");
    }

    /** The eye's distance does not matter, only its direction (the ray's direction need not be unit length). */
    @Test
    public void onlyTheEyesDirectionMatters() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 0.01)).light(v(3, 0, 4), v(25, 25, 25));
        p.check(shiny(v(0.5, 0.5, 0.5), v(1, 0.5, 0.25), 2), v(1.3, 0.85, 0.625), "as from straight above at any distance");
    }

    /** A large exponent: (n·h)^200 with (n·h)² = 0.9 is 0.9^100. */
    @Test
    public void aLargeExponent() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 7)).light(v(3, 0, 4), v(25, 25, 25));
        double highlight = Math.pow(0.9, 100);
        p.check(shiny(v(0, 0, 0), v(1, 1, 1), 200), v(highlight, highlight, highlight), "(n·h)^200 = 0.9^100");
    }

    /**
     * The course's convention: the highlight is not cut off where the light is behind the surface.
     * Eye along (0.6, 0, 0.8), light along (−0.8, 0, −0.6) at distance 5: n·l = −0.6 (no diffuse term),
     * but h = normalize(−0.2, 0, 0.2) gives n·h = √½, so with p = 2 the highlight is 0.5 · ks · 50/25.
     */
    @Test
    @Points(2)
    public void theHighlightIsNotCutOffBehindTheSurface() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(3, 0, 4)).light(v(-4, 0, -3), v(50, 50, 50));
        p.check(shiny(v(1, 1, 1), v(0.2, 0.4, 0.6), 2), v(0.2, 0.4, 0.6),
                "no diffuse term (n·l < 0), but the highlight ks · (n·h)² · I/r² = ks · 0.5 · 2 still counts, as in the course's renderer");
    }

    /** Where n·h < 0 there is no highlight, even with an odd exponent (never negative). */
    @Test
    public void noNegativeHighlight() {
        // Eye grazing from +x, light far below the surface toward −x: both factors' cosines negative.
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(5, 0, 0.1)).light(v(-1, 0, -5), v(10, 10, 10)).light(v(0, 0, 1), v(1, 1, 1));
        // Only the second light counts: straight above, h = normalize(l + e) with e nearly +x, l = +z.
        Vec3 e = v(5, 0, 0.1).normalized();
        Vec3 h = v(0, 0, 1).plus(e).normalized();
        double highlight = Math.pow(h.z, 3);
        p.check(shiny(v(0.5, 0.5, 0.5), v(1, 1, 1), 3), v(0.5 + highlight, 0.5 + highlight, 0.5 + highlight),
                "the light below the surface adds nothing; the one above kd · 1 + ks · (n·h)³");
    }

    /** Three lights, the middle one blocked: the other two add up, diffuse and highlight each. */
    @Test
    @Points(2)
    public void aBlockedLightAddsNeitherTerm() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 7)).light(v(3, 0, 4), v(25, 25, 25)).blockedLight(v(0, 0, 2), v(40, 40, 40))
                .light(v(0, 0, 1), v(1, 2, 3));
        // First light: (1.3, 0.85, 0.625) as above; the third straight above: (kd + ks) ⊙ (1, 2, 3) / 1.
        p.check(shiny(v(0.5, 0.5, 0.5), v(1, 0.5, 0.25), 2), v(1.3 + 1.5, 0.85 + 2, 0.625 + 2.25), "the blocked light's share left out");
    }

    /** A texture's color at the hit replaces kd, never ks. */
    @Test
    public void aTextureReplacesTheDiffuseColorOnly() {
        Phong shader = shiny(v(1, 1, 1), v(0.5, 0.5, 0.5), 10);
        shader.setTexture(new OneColor(v(0.2, 0.4, 0.6)));
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 3)).light(v(0, 0, 2), v(4, 4, 4));
        p.check(shader, v(0.7, 0.9, 1.1), "the texture's color + ks, times 4/4");
    }
}
