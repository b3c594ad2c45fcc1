package ray.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import ray.accel.Acceleration;
import ray.accel.SearchCounter;
import ray.accuracy.LogLogPlot;
import ray.render.RenderPlan;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneLoader;
import ray.surface.Surface;
import ray.surface.TriangleSet;

/**
 * {@code gradle treeBench}: what a tree buys as a mesh grows, for the plain loop ({@code --accel
 * none}), the students' tree as the solution writes it ({@code student}) and the framework's
 * ({@code bvh}): the bumpy sphere at 80 to 81,920 triangles, rendered on one thread, the three modes
 * interleaved and each timed at its best of several renders (so the machine's drift falls on all
 * three alike). Writes build/bench/tree-cost.md (time and boxes and primitives per ray) and
 * tree-cost.svg (time per ray against triangles, log–log).
 */
public final class TreeCostBench {
    private static final Acceleration[] MODES = {Acceleration.NONE, Acceleration.STUDENT, Acceleration.BVH};

    private TreeCostBench() {
    }

    public static void main(String[] args) throws IOException {
        Path out = Paths.get(args[0]);
        int repeats = args.length > 1 ? Integer.parseInt(args[1]) : 5;
        List<Path> scenes = MeshScenes.writeSizeSeries(out.resolve("tree-scenes"), 96, 72);
        StringBuilder md = new StringBuilder("# Tree cost against mesh size\n\n"
                + "The bumpy sphere on a ground, 96×72, one sample, one thread; best of " + repeats + " renders, the modes interleaved.\n"
                + "Time is the render's wall time per traced ray (camera and shadow); tests are per camera ray.\n\n"
                + "| triangles | mode | build (ms) | render (ms) | µs per ray | primitives per camera ray | boxes per camera ray | vs linear |\n"
                + "|---:|---|---:|---:|---:|---:|---:|---:|\n");
        Map<Acceleration, List<LogLogPlot.Point>> series = new EnumMap<>(Acceleration.class);
        for (Acceleration mode : MODES) {
            series.put(mode, new ArrayList<>());
        }
        for (Path file : scenes) {
            Scene scene = SceneLoader.load(file);
            int triangles = triangles(scene);
            // The students' tree is built on its first search; build it here to time it alone.
            long buildStart = System.nanoTime();
            for (Surface surface : scene.getSurfaces().children()) {
                if (surface instanceof TriangleSet && ((TriangleSet) surface).hasTree()) {
                    ((TriangleSet) surface).studentTree();
                }
            }
            double studentBuild = (System.nanoTime() - buildStart) / 1e6;
            Map<Acceleration, RenderResult> best = new EnumMap<>(Acceleration.class);
            int runs = triangles > 20_000 ? Math.max(2, repeats / 2) : repeats;
            for (int r = 0; r < runs; r++) {
                for (Acceleration mode : MODES) {
                    RenderResult result = new Renderer(RenderPlan.of(scene).withAcceleration(mode), 1).render();
                    if (!best.containsKey(mode) || result.seconds < best.get(mode).seconds) {
                        best.put(mode, result);
                    }
                }
            }
            double linearPerRay = perRay(best.get(Acceleration.NONE));
            for (Acceleration mode : MODES) {
                RenderResult r = best.get(mode);
                double us = perRay(r);
                series.get(mode).add(new LogLogPlot.Point(triangles, us, null));
                md.append(String.format(Locale.ROOT, "| %,d | %s | %s | %.1f | %.3f | %.1f | %.1f | %.1f× |\n", triangles, mode.option(),
                        mode == Acceleration.STUDENT ? String.format(Locale.ROOT, "%.1f", studentBuild) : "",
                        r.seconds * 1e3, us, (double) r.rays.intersectionTests[SearchCounter.CAMERA] / r.rays.camera,
                        (double) r.rays.boxTests[SearchCounter.CAMERA] / r.rays.camera, linearPerRay / us));
            }
            System.out.println("measured " + file.getFileName());
        }
        LogLogPlot plot = new LogLogPlot("Time per ray against mesh size", "triangles in the mesh", "µs per ray (one thread)")
                .line("plain loop (none)", "#c0392b", false, series.get(Acceleration.NONE))
                .line("students' tree (student)", "#2471a3", false, series.get(Acceleration.STUDENT))
                .line("framework's tree (bvh)", "#229954", true, series.get(Acceleration.BVH));
        Files.write(out.resolve("tree-cost.md"), md.toString().getBytes(StandardCharsets.UTF_8));
        Files.write(out.resolve("tree-cost.svg"), plot.toSvg().getBytes(StandardCharsets.UTF_8));
        System.out.println(md);
    }

    private static int triangles(Scene scene) {
        int n = 0;
        for (Surface surface : scene.getSurfaces().children()) {
            n += surface instanceof TriangleSet ? ((TriangleSet) surface).triangleCount() : 0;
        }
        return n;
    }

    private static double perRay(RenderResult r) {
        return r.seconds * 1e6 / r.rays.total();
    }
}
