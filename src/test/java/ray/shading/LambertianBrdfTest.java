package ray.shading;

import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Checks LambertianBrdf.value, f = ρd/π, with values worked out in each comment: the same for every
 * pair of directions, per channel, and the course's own check value of a lit point.
 */
@Points(1)
public class LambertianBrdfTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final Vec3 UP = v(0, 0, 1);

    /** Light and eye along the normal: f = ρd/π = 0.5/π in every channel. */
    @Test
    @Points(2)
    public void aGrayMatteIsItsReflectanceOverPi() {
        double f = 0.5 / Math.PI;
        BrdfValues.check(new LambertianBrdf(), v(0.5, 0.5, 0.5), UP, UP, UP, v(f, f, f), "ρd/π, with π = Math.PI");
    }

    /** Each channel on its own: ρd = (0, 0.5, 0.25) gives (0, 0.5/π, 0.25/π). */
    @Test
    public void eachChannelOnItsOwn() {
        BrdfValues.check(new LambertianBrdf(), v(0, 0.5, 0.25), UP, v(0.6, 0, 0.8), v(0, -0.8, 0.6), v(0, 0.5 / Math.PI, 0.25 / Math.PI),
                "ρd/π channel by channel");
    }

    /** A matte surface looks the same from everywhere, lit from anywhere: a grazing light, a grazing eye, the two on one side. */
    @Test
    @Points(2)
    public void theDirectionsDoNotMatter() {
        Vec3 rhoD = v(0.9, 0.3, 0.1);
        Vec3 expected = rhoD.times(1 / Math.PI);
        Vec3[][] pairs = {{v(1, 0, 0), UP}, {UP, v(0, 1, 0)}, {v(0.6, 0, 0.8), v(0.6, 0, 0.8)}, {v(0, 0.28, 0.96), v(-0.96, 0, 0.28)}};
        for (Vec3[] pair : pairs) {
            BrdfValues.check(new LambertianBrdf(), rhoD, UP, pair[0], pair[1], expected, "ρd/π, whatever l and v are: f has no cosine in it");
        }
    }

    /**
     * The course's own check: the point (0, 1, 0) with normal +y, seen from (0, 2, 0), ρd = (0, 0.5, 0.5),
     * a light at (5, 5, 5) of intensity 100: n·l = 4/√66 and r² = 66, so the point sends back
     * ρd/π · 100 · (4/√66)/66 = (0, 0.37300451811919, 0.37300451811919)/π.
     */
    @Test
    @Points(2)
    public void theCoursesLitPoint() {
        Vec3 reflected = BrdfValues.reflected(new LambertianBrdf(), v(0, 0.5, 0.5), v(0, 1, 0), v(0, 1, 0), v(0, 2, 0), v(5, 5, 5),
                v(100, 100, 100));
        double g = 0.37300451811919 / Math.PI;
        assertVec("f ⊙ I · (n·l)/r² with f = LambertianBrdf.value", v(0, g, g), reflected, 1e-12);
    }
}
