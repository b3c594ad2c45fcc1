package ray.bvh;

/**
 * What the framework keeps for the box code of the hierarchy ({@link BoundingBoxes}, which students
 * write): the bound on the rounding error of the slab test's distances.
 */
public abstract class BoxGeometry {
    /** Half a unit in the last place of 1: the relative error of one rounded double operation. */
    protected static final double UNIT_ROUNDOFF = 0x1p-53;
    /**
     * γ₃ = 3u/(1 − 3u): a slab distance (max − o)·(1/d) is three rounded operations, so its computed
     * value is within a factor 1 ± γ₃ of the exact one (Pharr, Jakob and Humphreys, Physically Based
     * Rendering, 3rd ed., section 3.9.2, "Robust ray–bounds intersections").
     */
    protected static final double GAMMA_3 = 3 * UNIT_ROUNDOFF / (1 - 3 * UNIT_ROUNDOFF);

    /** Checks nothing: it has no state. */
    public void complete() {
    }
}
