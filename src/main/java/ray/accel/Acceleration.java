package ray.accel;

/**
 * How the renderer's searches run. None changes the image (a test renders every shipped scene with
 * the framework's tree and without, and compares the PNGs byte for byte; the students' tree is
 * checked against the plain loop); they differ in time and in the work that {@code --stats} counts.
 * The student's {@code Group} loop is linear in every mode.
 */
public enum Acceleration {
    /**
     * The framework's trees: boxes and meshes searched through their bounding volume hierarchy
     * ({@link Bvh}), placed groups skipped when a ray misses their box, and shadow rays that stop at
     * the first blocker.
     */
    BVH("bvh", "framework"),
    /**
     * As {@link #BVH}, but boxes and meshes searched through the students' hierarchy
     * ({@code ray.bvh.BvhTree}): built by their code and searched by it.
     */
    STUDENT("student"),
    /**
     * Plain linear loops: every triangle of a box or mesh tested by every ray that reaches it, no
     * box tests, and shadow rays that search for the closest hit as camera rays do.
     */
    NONE("none");

    private final String option;
    private final String[] otherSpellings;

    Acceleration(String option, String... otherSpellings) {
        this.option = option;
        this.otherSpellings = otherSpellings;
    }

    /** The option's spelling: {@code bvh}, {@code student} or {@code none}. */
    public String option() {
        return option;
    }

    /** Whether boxes are tested before what they hold, and shadow rays stop at the first blocker: every mode but {@link #NONE}. */
    public boolean accelerated() {
        return this != NONE;
    }

    /**
     * The mode a render runs in unless told otherwise: the students' tree ({@link #STUDENT}) when the
     * assignment has them write it (the task {@value #STUDENTS_TREE_TASK}), so that every render of
     * theirs, and every render test, searches boxes and meshes with it; else the framework's ({@link #BVH}).
     */
    public static Acceleration ofAssignment() {
        return ray.assignment.Assignment.current().isChosen(STUDENTS_TREE_TASK) ? STUDENT : BVH;
    }

    /** The task in which students write the tree {@link #STUDENT} searches with. */
    public static final String STUDENTS_TREE_TASK = "bvh";

    /** The mode an option names ({@code framework} is {@code bvh}), or null. */
    public static Acceleration named(String value) {
        for (Acceleration mode : values()) {
            if (mode.option.equals(value) || java.util.Arrays.asList(mode.otherSpellings).contains(value)) {
                return mode;
            }
        }
        return null;
    }

    /** Every spelling an option may take, for a usage message: "bvh (or framework), student or none". */
    public static String spellings() {
        java.util.List<String> each = new java.util.ArrayList<>();
        for (Acceleration mode : values()) {
            each.add(mode.option + (mode.otherSpellings.length == 0 ? "" : " (or " + String.join(", ", mode.otherSpellings) + ")"));
        }
        return String.join(", ", each.subList(0, each.size() - 1)) + " or " + each.get(each.size() - 1);
    }
}
