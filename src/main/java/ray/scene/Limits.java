package ray.scene;

/**
 * The largest input the framework accepts. Past these, a scene or mesh gets a clear one-line
 * error instead of running out of memory (or overflowing an {@code int} array size) minutes later.
 * Each limit is far above what the course's scenes need; docs/robustness.md lists them with the
 * memory they stand for.
 */
public final class Limits {
    /** Widest or tallest image, in pixels. */
    public static final int MAX_IMAGE_SIDE = 8192;
    /**
     * Most pixels in one image (4096 × 4096): the renderer keeps 3 doubles per pixel (24 bytes,
     * 400 MB here) and the PNG writer 4 bytes more, which fits a 1 GB heap.
     */
    public static final long MAX_PIXELS = 4096L * 4096L;
    /** Most samples per pixel (a 256 × 256 grid). */
    public static final int MAX_SAMPLES = 256 * 256;
    /** Most triangles in one mesh, after polygons are split into fans (about 24 bytes each in MeshData). */
    public static final int MAX_MESH_TRIANGLES = 4_000_000;
    /** Most vertices, and most normals, in one mesh file (24 bytes each). */
    public static final int MAX_MESH_VERTICES = 4_000_000;
    /** Longest line of an OBJ file, in characters: a longer one is not an OBJ statement. */
    public static final int MAX_OBJ_LINE = 64 * 1024;
    /** Largest scene file: the whole file is read before it is parsed. Hand-written scenes are kilobytes. */
    public static final long MAX_SCENE_BYTES = 16L * 1024 * 1024;
    /** Deepest nesting of elements in a scene file; the loader recurses once per level. */
    public static final int MAX_NESTING = 64;

    private Limits() {
    }

    /** Checks an image size, in the words a scene error uses; null when it is within the limits. */
    static String imageSizeProblem(int width, int height) {
        if (width > MAX_IMAGE_SIDE || height > MAX_IMAGE_SIDE) {
            return "image size " + width + " " + height + " is too large; expected each side at most " + MAX_IMAGE_SIDE;
        }
        if ((long) width * height > MAX_PIXELS) {
            return "image size " + width + " " + height + " has " + (long) width * height
                    + " pixels; expected at most " + MAX_PIXELS + " (e.g. 4096 4096)";
        }
        return null;
    }

    /** Checks a samples-per-pixel count; null when it is within the limit. */
    static String samplesProblem(int samples) {
        return samples > MAX_SAMPLES ? "samples is " + samples + "; expected at most " + MAX_SAMPLES + " per pixel" : null;
    }
}
