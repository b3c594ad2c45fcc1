package ray.surface;

/**
 * What a camera ray's closest hit is, by the kind of primitive that reported it: the kinds the
 * renderer's pixel-kind record tells apart, each with the student task whose code found it. A mesh's
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
    SPHERE(2, "a sphere", "spheres"),
    TRIANGLE(3, "a triangle", "triangles"),
    /** Task 6, the extra credit. */
    CYLINDER(6, "a cylinder", "cylinders"),
    /** A primitive of any other class (no scene file makes one: a test's or a study's own surface). */
    OTHER(0, "another surface", "other surfaces"),
    /** No hit: the ray left the scene and the pixel shows the background color. */
    BACKGROUND(0, "the background", "the background");

    private static final SurfaceKind[] ALL = values();

    /** The number of the student task whose intersection code finds this kind, or 0 when none does. */
    public final int task;
    private final String one;
    private final String many;

    SurfaceKind(int task, String one, String many) {
        this.task = task;
        this.one = one;
        this.many = many;
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
