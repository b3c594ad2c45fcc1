package ray.bvh;

/**
 * The students' boxes or tree broke a rule the framework checks before it searches with them (a
 * primitive without a box, a tree that breaks {@link TreeInvariants}): their code returned, so no
 * student frame is on the stack, yet the bvh task is to blame, whichever test rendered the mesh.
 */
public final class BrokenTree extends IllegalStateException {
    private static final long serialVersionUID = 1L;

    /** Whether the build returned no tree at all (null), as the handout's stub does. */
    public final boolean nothingBuilt;

    public BrokenTree(String message) {
        this(message, false);
    }

    BrokenTree(String message, boolean nothingBuilt) {
        super(message);
        this.nothingBuilt = nothingBuilt;
    }

    /** How a command names it to the student, in one line: where the framework's check ran says nothing. */
    public String inOneLine() {
        return "your tree cannot be searched: " + getMessage();
    }
}
