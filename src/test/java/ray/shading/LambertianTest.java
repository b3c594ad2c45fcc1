package ray.shading;

import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Checks Lambertian.shade on points lit by hand-placed lights, each value worked out in its comment:
 * L = Σ over the lights that reach the point of kd ⊙ I · max(0, n·l) / r².
 */
@Points(1)
public class LambertianTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static Lambertian matte(Vec3 kd) {
        Lambertian shader = new Lambertian(kd);
        shader.complete();
        return shader;
    }

    /** A light of intensity 4 straight above at distance 2: n·l = 1, r² = 4, so L = kd. */
    @Test
    @Points(2)
    public void oneLightStraightAbove() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 2)).light(v(0, 0, 2), v(4, 4, 4));
        p.check(matte(v(0.5, 0.25, 1)), v(0.5, 0.25, 1), "kd ⊙ I · (n·l)/r² = kd · 4 · 1/4");
    }

    /** A slanted light 5 away (n·l = 0.8, r² = 25) of a colored intensity: each channel its own. */
    @Test
    @Points(2)
    public void aSlantedColoredLight() {
        LitPoint p = new LitPoint(v(1, 2, 3), v(0, 0, 1), v(1, 2, 10)).light(v(4, 2, 7), v(50, 25, 100));
        // kd ⊙ I = (20, 20, 20); · 0.8 / 25 = 0.64.
        p.check(matte(v(0.4, 0.8, 0.2)), v(0.64, 0.64, 0.64), "kd ⊙ I · (n·l)/r² = (0.4·50, 0.8·25, 0.2·100) · 0.8/25");
    }

    /** The same light twice as far: a quarter of the light. */
    @Test
    public void twiceAsFarIsAQuarter() {
        LitPoint near = new LitPoint(Vec3.ZERO, v(0, 1, 0), v(0, 5, 5)).light(v(0, 3, 0), v(9, 9, 9));
        LitPoint far = new LitPoint(Vec3.ZERO, v(0, 1, 0), v(0, 5, 5)).light(v(0, 6, 0), v(9, 9, 9));
        near.check(matte(v(1, 1, 1)), v(1, 1, 1), "I/r² = 9/9");
        far.check(matte(v(1, 1, 1)), v(0.25, 0.25, 0.25), "I/r² = 9/36");
    }

    /** Three lights add up: straight above (1), 45° off (cos = √½, r² = 2) and slanted (0.8, r² = 25). */
    @Test
    @Points(2)
    public void threeLightsAddUp() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, -1, 3)).light(v(0, 0, 1), v(1, 0, 0)).light(v(1, 0, 1), v(0, 2, 0))
                .light(v(-3, 0, 4), v(0, 0, 25));
        double r = 1;
        double g = 2 * Math.sqrt(0.5) / 2;
        double b = 25 * 0.8 / 25;
        p.check(matte(v(1, 1, 1)), v(r, g, b), "the sum of each light's I · (n·l)/r²: (1, 2·√½/2, 25·0.8/25)");
    }

    /** Of three lights, the blocked one adds nothing; the shadow test is asked about lights by their positions. */
    @Test
    @Points(2)
    public void aBlockedLightAddsNothing() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, -1, 3)).light(v(0, 0, 1), v(1, 0, 0)).blockedLight(v(1, 0, 1), v(0, 2, 0))
                .light(v(-3, 0, 4), v(0, 0, 25));
        p.check(matte(v(1, 1, 1)), v(1, 0, 0.8), "the blocked light's share left out");
    }

    /** With every light blocked the point is black, however bright the lights; unblocked, the same lights light it. */
    @Test
    public void everyLightBlockedIsBlack() {
        LitPoint lit = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 3)).light(v(0, 0, 1), v(100, 100, 100)).light(v(0, 0, 2), v(8, 8, 8));
        lit.check(matte(v(1, 1, 1)), v(102, 102, 102), "100/1 + 8/4");
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 3)).blockedLight(v(0, 0, 1), v(100, 100, 100))
                .blockedLight(v(0, 0, 2), v(8, 8, 8));
        p.check(matte(v(1, 1, 1)), Vec3.ZERO, "no light reaches it");
    }

    /** A light behind the surface (n·l < 0) adds nothing: never a negative share. */
    @Test
    @Points(2)
    public void aLightBehindTheSurfaceAddsNothing() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 3)).light(v(0, 0, -2), v(4, 4, 4)).light(v(0, 0, 2), v(4, 4, 4));
        p.check(matte(v(1, 1, 1)), v(1, 1, 1), "only the light in front: 4 · 1/4");
    }

    /** No lights: black; one light: lit. */
    @Test
    public void noLightsIsBlack() {
        LitPoint lit = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 3)).light(v(0, 0, 2), v(4, 4, 4));
        lit.check(matte(v(1, 1, 1)), v(1, 1, 1), "4 · 1/4");
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 3));
        p.check(matte(v(1, 1, 1)), Vec3.ZERO, "");
    }

    /** A texture's color at the hit replaces the diffuse color (diffuseColorAt). */
    @Test
    @Points(2)
    public void aTexturesColorReplacesTheDiffuseColor() {
        Lambertian shader = matte(v(1, 1, 1));
        shader.setTexture(new OneColor(v(0.2, 0.4, 0.6)));
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 3)).light(v(0, 0, 2), v(4, 4, 4));
        p.check(shader, v(0.2, 0.4, 0.6), "the texture's color · 4 · 1/4");
    }

    /** A point in front of a light asks the shadow test about it (by its position, as the other tests check). */
    @Test
    public void theShadowTestAsksAboutTheLight() {
        LitPoint p = new LitPoint(Vec3.ZERO, v(0, 0, 1), v(0, 0, 3)).light(v(0, 1, 2), v(5, 5, 5));
        p.shade(matte(v(1, 1, 1)));
        assertTrue("shading " + p.describe() + " asked no shadow test (context.unoccluded); a light counts only if nothing blocks it",
                !p.asked.isEmpty());
    }
}
