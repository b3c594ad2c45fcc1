package ray.accel;

/**
 * What the searches of one thread cost, counted where the work is done: ray–primitive intersection
 * tests (calls of a primitive's {@code intersect}) and bounding boxes tested (BVH nodes and the
 * boxes of placed groups), per kind of ray. SceneShading says which kind of ray it is searching for
 * before each search; the surfaces add their counts after it. Not shared between threads.
 */
public final class SearchCounter {
    public static final int CAMERA = 0;
    public static final int SHADOW = 1;
    public static final int REFLECTION = 2;
    public static final int KINDS = 3;

    private int kind = CAMERA;
    private final long[] tests = new long[KINDS];
    private final long[] boxes = new long[KINDS];

    /** The kind of ray the next searches are for: {@link #CAMERA}, {@link #SHADOW} or {@link #REFLECTION}. */
    public void searchingFor(int kind) {
        this.kind = kind;
    }

    public int kind() {
        return kind;
    }

    public void count(long intersectionTests, long boxesTested) {
        tests[kind] += intersectionTests;
        boxes[kind] += boxesTested;
    }

    public long tests(int kind) {
        return tests[kind];
    }

    public long boxes(int kind) {
        return boxes[kind];
    }
}
