package ray.surface;

/**
 * What a camera ray's closest hit is, by the kind of primitive that reported it: the kinds the
 * renderer's pixel-kind record tells apart, each with the task whose code found it (by its id in the
 * table of tasks, and its number in this assignment). A mesh's
 * or a box's triangles are triangles, and a primitive inside a transformed group is that primitive
 * (a hit's {@code surface} is always the primitive itself). Each primitive says its kind
 * ({@link Surface#kind()}): the shapes the framework gives each task ({@link SphereSurface},
 * {@link TriangleSurface}, {@link CylinderSurface}) say theirs, so a student's class, or any variant of
 * it, is recognized whatever class loader made it.
 *
 * <p>The declaration order is the order of preference where counts tie: a surface before the
 * background.
 */
public enum SurfaceKind {
    SPHERE("sphere", "a sphere", "spheres"),
    TRIANGLE("triangle", "a triangle", "triangles"),
    CYLINDER("cylinder", "a cylinder", "cylinders"),
    /** A primitive of any other class (no scene file makes one: a test's or a study's own surface). */
    OTHER(null, "another surface", "other surfaces"),
    /** No hit: the ray left the scene and the pixel shows the background color. */
    BACKGROUND(null, "the background", "the background");

    private static final SurfaceKind[] ALL = values();

    /** The id (in the table of tasks) of the task whose intersection code finds this kind, or null when none does. */
    public final String taskId;
    private final String one;
    private final String many;

    SurfaceKind(String taskId, String one, String many) {
        this.taskId = taskId;
        this.one = one;
        this.many = many;
    }

    /** That task's number in this assignment, or 0 when there is none or it ships solved. */
    public int task() {
        return taskId == null ? 0 : ray.assignment.Assignment.current().number(taskId);
    }

    /** The kind of the primitive a hit record names ({@link #OTHER} for null). */
    public static SurfaceKind of(Surface primitive) {
        return primitive == null ? OTHER : primitive.kind();
    }

    /**
     * How a message names {@code count} pixels of this kind, with the task: "triangles (Task 3)",
     * "a triangle (Task 3)" for one, "the background" (no task).
     */
    public String phrase(int count) {
        int task = task();
        return (count == 1 ? one : many) + (task > 0 ? " (Task " + task + ")" : "");
    }

    /** The kind with the most votes ({@code votes} indexed by ordinal), the first declared on a tie; clears the votes. */
    public static SurfaceKind mostVoted(int[] votes) {
        int best = 0;
        for (int k = 1; k < votes.length; k++) {
            if (votes[k] > votes[best]) {
                best = k;
            }
        }
        java.util.Arrays.fill(votes, 0);
        return ALL[best];
    }

    public static SurfaceKind ofOrdinal(int ordinal) {
        return ALL[ordinal];
    }

    public static int count() {
        return ALL.length;
    }
}
