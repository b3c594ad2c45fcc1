package ray.inspect;

import java.io.PrintWriter;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.camera.Camera;
import ray.math.Vec3;
import ray.render.TaskProbes.Part;
import ray.scene.Scene;

/**
 * Explains one pixel of a scene, the way a student would trace it by hand: which ray the camera
 * makes, what every surface says about it, which hit the scene's group picks, how the shader
 * lights it, and the pixel's radiance and 8-bit value (from the real renderer, so it equals the
 * rendered PNG's pixel). Student code that throws is reported in one line and the trace goes on
 * where it can.
 */
public final class PixelTrace {
    private final Scene scene;
    private final String sceneLabel;
    private final SurfaceNames names;
    private final boolean allTriangles;
    private final int samplesOverride;

    /**
     * @param sceneLabel      how to name the scene in the output (its path)
     * @param allTriangles    list every triangle of meshes and boxes instead of a summary line
     * @param samplesOverride samples per pixel as {@code ray1 render --samples} takes it, or 0 for the scene's
     */
    public PixelTrace(Scene scene, String sceneLabel, boolean allTriangles, int samplesOverride) {
        this.scene = scene;
        this.sceneLabel = sceneLabel;
        this.names = new SurfaceNames();
        this.allTriangles = allTriangles;
        this.samplesOverride = samplesOverride;
    }

    /** The problem with pixel (x, y) counted from the top left, or null when it is in the image. */
    public static String outOfRange(Scene scene, String sceneLabel, int x, int y) {
        int w = scene.getWidth();
        int h = scene.getHeight();
        if (x >= 0 && x < w && y >= 0 && y < h) {
            return null;
        }
        return "pixel (" + x + ", " + y + ") is outside the " + w + "×" + h + " image of " + sceneLabel + ": x goes from 0 to "
                + (w - 1) + " (from the left), y from 0 to " + (h - 1) + " (from the top)";
    }

    /** Prints the trace of pixel (x, y), x from the left and y from the top; returns its 8-bit value, or null if it could not be rendered. */
    public int[] run(int x, int y, PrintWriter out) {
        int w = scene.getWidth();
        int h = scene.getHeight();
        PixelCoordinates pixel = new PixelCoordinates(scene, x, y);
        int i = pixel.i;
        int j = pixel.j;
        double u = pixel.u;
        double v = pixel.v;
        out.println("Pixel x = " + x + ", y = " + y + " of " + sceneLabel + " (" + w + "×" + h + " pixels)");
        out.println("  x counts from the left and y from the top, as an image viewer shows the PNG.");
        out.println(Fmt.row("  ", "(i, j)", "(" + i + ", " + j + ")   the renderer's pixel: i = x, j = " + (h - 1) + " − y counts from the bottom"));
        out.println(Fmt.row("  ", "(u, v)", "((i + ½)/" + w + ", (j + ½)/" + h + ") = (" + Fmt.num(u) + ", " + Fmt.num(v) + ")   the pixel's center"));
        out.println();

        Vec3 centerRadiance = traceCenterRay(u, v, out);

        out.println("Pixel value");
        PixelValue value;
        try {
            value = PixelValue.render(scene, i, j, samplesOverride);
        } catch (RuntimeException | StackOverflowError e) {
            out.println("  the renderer threw " + Failure.oneLine(e) + ", so the pixel has no value");
            return null;
        }
        int n = (int) Math.round(Math.sqrt(value.samples));
        out.println(Fmt.row("  ", "samples", value.samples == 1 ? "1 per pixel: the center ray above"
                : value.samples + " per pixel, on a " + n + "×" + n + " grid; the trace above follows the pixel's center,"
                        + " the value averages all " + value.samples));
        out.println(Fmt.row("  ", "rays", "1 camera ray per sample, " + value.shadowRays + " shadow, " + value.reflectionRays + " reflection"));
        out.println(Fmt.row("  ", "radiance", Fmt.vec(value.radiance) + "   (linear RGB, the renderer's result for this pixel)"));
        if (value.samples == 1 && centerRadiance != null && !sameUpToRounding(centerRadiance, value.radiance)) {
            out.println(Fmt.row("  ", "!", "the trace computed " + Fmt.vec(centerRadiance) + " for the center ray; the renderer's"
                    + " value above is the one in the image"
                    + (Part.RAY_TRACER.isStudents()
                            ? " (the renderer gets every ray's color from RayTracer.shadeRay: the background on a miss, else the"
                                    + " closest hit shaded; see TODO(Task " + Part.RAY_TRACER.task() + "))"
                            : "")));
        }
        double exposure = scene.getExposure();
        out.println(Fmt.row("  ", "exposure", Fmt.num(exposure) + ", exposure × radiance = " + Fmt.vec(value.radiance.times(exposure))));
        out.println(Fmt.row("  ", "8-bit RGB", Fmt.rgb8(value.rgb8) + "   (clamp to [0, 1], x^(1/2.2), floor(255·x + ½)):"
                + " the PNG's pixel at x = " + x + ", y = " + y));
        return value.rgb8;
    }

    /**
     * Whether the trace's radiance is the renderer's but for rounding: the trace follows the scene in
     * its own coordinates, the renderer from the camera's frame (ray.scene.CameraFrame), so the two
     * may differ in the last digits, never by more than a billionth.
     */
    private static boolean sameUpToRounding(Vec3 traced, Vec3 rendered) {
        return Math.abs(traced.x - rendered.x) <= 1e-9 * Math.max(1, Math.abs(rendered.x))
                && Math.abs(traced.y - rendered.y) <= 1e-9 * Math.max(1, Math.abs(rendered.y))
                && Math.abs(traced.z - rendered.z) <= 1e-9 * Math.max(1, Math.abs(rendered.z));
    }

    /** The camera ray, the surfaces, the closest hit and its shading; returns the ray's radiance, or null if it could not be computed. */
    private Vec3 traceCenterRay(double u, double v, PrintWriter out) {
        Camera camera = scene.getCamera();
        String call = camera.getClass().getSimpleName() + ".generateRay(" + Fmt.num(u) + ", " + Fmt.num(v) + ")";
        out.println("Camera ray: " + call);
        Ray ray;
        try {
            ray = camera.generateRay(u, v);
        } catch (RuntimeException | StackOverflowError e) {
            out.println("  ! it threw " + Failure.oneLine(e));
            out.println();
            return null;
        }
        String problem = CameraRayCheck.problem(camera, ray);
        if (ray != null && ray.origin != null && ray.direction != null) {
            out.println(Fmt.row("  ", "origin", Fmt.vec(ray.origin)));
            out.println(Fmt.row("  ", "direction", Fmt.vec(ray.direction) + "   (need not be unit length: t counts multiples of it)"));
            out.println(Fmt.row("  ", "segment", "t from " + Fmt.num(ray.start) + " to " + Fmt.num(ray.end)));
        }
        if (problem != null) {
            out.println("  ! " + problem);
        }
        out.println();
        if (ray == null || ray.origin == null || ray.direction == null) {
            return null;
        }

        List<ProbeNode> roots = ProbeTree.of(scene.getSurfaces(), ray);
        List<ProbeNode> primitives = ProbeTree.primitives(roots);
        ProbeNode nearest = ProbeTree.nearest(primitives);
        out.println("Surfaces, in scene order, each tested alone with its own intersect (a fresh record, the whole ray):");
        if (roots.isEmpty()) {
            out.println("  (the scene has no surfaces)");
        }
        new ProbePrinter(names, allTriangles, nearest).print(roots, "  ", out);
        out.println();

        return new ClosestHitReport(scene, names, out).explain(ray, roots, nearest);
    }
}
