package ray.numerics;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;
import ray.numerics.Reintersection.Kind;
import ray.numerics.Reintersection.Tally;

/**
 * No shadow acne: rays that leave a hit (reflection rays into the half-space in front of it, shadow
 * rays to lights there, and on closed surfaces hit from inside, shadow rays to lights inside)
 * never hit the same surface again, for every case of the catalogue in {@link Reintersection}:
 * spheres hit from outside and inside, a transformed ellipsoid, a huge ground sphere near the
 * origin, triangles (plain, thin, seen from far away, smooth-shaded, transformed), and a closed
 * mesh hit near its shared edges and vertices from outside and inside; sizes and positions
 * 10^−4…10^6.
 *
 * <p>Per case, 400 surfaces with 10 leaving and 10 shadow rays each (about 8000 rays; 4000 shadow
 * rays for the inside cases): 0 re-hits allowed, with the solution's intersection code and with
 * textbook code (a quadratic sphere without re-projection, a Cramer's-rule triangle). The sweep
 * ({@link ReintersectionSweep}, 10^6 rays per case) measured 0 re-hits for both, and the margin:
 * with the solution's code, offsets of 4·ε·scale already re-hit 0 times and 2·ε·scale up to 0.39%
 * (a transformed sphere); textbook triangles on a closed mesh re-hit 2 per million at 256·ε·scale
 * and 0 at the renderer's 1024.
 *
 * <p>The catalogue does find acne: with no offset (t_min = 0) 23% (ground sphere) to 50% of the same
 * rays re-hit, and this test requires more than 10% for every case.
 */
@RunWith(Parameterized.class)
public class ReintersectionTest {
    private static final int SURFACES = 400;
    private static final int RAYS_PER_HIT = 10;

    @Parameters(name = "{0}")
    public static List<Object[]> kinds() {
        List<Object[]> list = new ArrayList<>();
        for (Kind kind : Kind.values()) {
            list.add(new Object[] {kind});
        }
        return list;
    }

    private final Kind kind;

    public ReintersectionTest(Kind kind) {
        this.kind = kind;
    }

    @Test
    public void rendererRaysNeverReHitTheSurfaceTheyLeave() {
        Tally tally = Reintersection.run(kind, Reintersection.FRAMEWORK, false, 7, SURFACES, RAYS_PER_HIT);
        assertTrue("too few rays ran: " + tally, tally.rays() >= SURFACES * RAYS_PER_HIT * 9 / 10);
        assertEquals(kind + ": " + tally, 0, tally.rehits());
    }

    @Test
    public void rendererRaysNeverReHitATextbookSurface() {
        Tally tally = Reintersection.run(kind, Reintersection.FRAMEWORK, true, 8, SURFACES, RAYS_PER_HIT);
        assertTrue("too few rays ran: " + tally, tally.rays() >= SURFACES * RAYS_PER_HIT * 9 / 10);
        assertEquals(kind + " (textbook intersection): " + tally, 0, tally.rehits());
    }

    /** pbrt-v4's error-bound offset is enough for the solution's own (robust) intersection code. */
    @Test
    public void errorBoundRaysNeverReHitTheSolutionsSurfaces() {
        Tally tally = Reintersection.run(kind, Reintersection.ERROR_BOUND, false, 10, SURFACES, RAYS_PER_HIT);
        assertTrue("too few rays ran: " + tally, tally.rays() >= SURFACES * RAYS_PER_HIT * 9 / 10);
        assertEquals(kind + " (error-bound offset): " + tally, 0, tally.rehits());
    }

    @Test
    public void raysWithoutAnOffsetOftenReHit() {
        Tally tally = Reintersection.run(kind, Reintersection.NO_OFFSET, false, 9, SURFACES / 4, RAYS_PER_HIT);
        assertTrue(kind + " without an offset should show acne, but: " + tally, tally.rate() > 0.10);
    }
}
