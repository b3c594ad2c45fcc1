package ray.accel;

/**
 * How the framework's own searches run. Neither changes the image (a test renders every shipped
 * scene both ways and compares the PNGs byte for byte); they differ in time and in the work that
 * {@code --stats} counts. The student's {@code Group} loop is linear either way.
 */
public enum Acceleration {
    /**
     * Boxes and meshes searched through their bounding volume hierarchy, placed groups skipped when
     * a ray misses their box, and shadow rays that stop at the first blocker.
     */
    BVH,
    /**
     * Plain linear loops: every triangle of a box or mesh tested by every ray that reaches it, no
     * box tests, and shadow rays that search for the closest hit as camera rays do.
     */
    NONE;

    /** The option's spelling: {@code bvh} or {@code none}. */
    public String option() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}
