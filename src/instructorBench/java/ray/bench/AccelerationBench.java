package ray.bench;

import com.google.gson.Gson;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import ray.accel.Acceleration;
import ray.render.RenderPlan;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneFiles;
import ray.scene.SceneLoader;

/**
 * {@code gradle accelBench}: what acceleration buys, measured in one run and written to
 * build/bench/acceleration.md (the tables of docs/performance.md's acceleration section):
 * <ol>
 * <li>every shipped scene rendered with {@code --accel bvh} and {@code --accel none} (2 threads,
 * best of several renders after warm-up), with the intersection and box tests each counted;</li>
 * <li>the three {@link MeshScenes} with the BVH on 1 and 2 threads, and without it where that
 * takes seconds rather than minutes;</li>
 * <li>the same three scenes rendered by Mitsuba 3 ({@code scalar_rgb}, all cores) through
 * src/instructorBench/mitsuba/render_mitsuba.py, when Python can import mitsuba (else the column says so).</li>
 * </ol>
 * Not JMH: each render takes from milliseconds to seconds, so a best-of-N after warm-up renders in
 * the same JVM is steady enough, and the whole run takes a few minutes.
 */
public final class AccelerationBench {
    private AccelerationBench() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Paths.get(args.length > 0 ? args[0] : "build/bench");
        String python = args.length > 1 ? args[1] : "python3";
        Files.createDirectories(out);
        StringBuilder md = new StringBuilder();
        md.append("## Shipped scenes, linear vs BVH (2 threads, best of 5 after 2 warm-up renders)\n\n")
                .append("| scene | plan's bvh | linear | BVH | speedup | tests per ray, linear | tests per ray, BVH | boxes per ray, BVH |\n")
                .append("|---|---|---|---|---|---|---|---|\n");
        for (Path file : SceneFiles.under(Paths.get("scenes"), Paths.get("scenes", "reference"))) {
            Scene scene = SceneLoader.load(file);
            RenderPlan plan = RenderPlan.of(scene);
            Timed none = time(plan.withAcceleration(Acceleration.NONE), 2, 2, 5);
            Timed bvh = time(plan, 2, 2, 5);
            String bvhEffect = plan.effects().stream().filter(e -> e.startsWith("bvh(")).findFirst().orElse("none");
            double rays = bvh.result.rays.total();
            md.append(String.format(Locale.ROOT, "| %s | %s | %s | %s | %.2f | %.1f | %.1f | %.1f |%n", SceneFiles.nameOf(file), bvhEffect,
                    ms(none.seconds), ms(bvh.seconds), none.seconds / bvh.seconds,
                    none.result.rays.totalIntersectionTests() / rays, bvh.result.rays.totalIntersectionTests() / rays,
                    bvh.result.rays.totalBoxTests() / rays));
            System.out.println("shipped " + file + ": " + ms(none.seconds) + " linear, " + ms(bvh.seconds) + " bvh");
        }

        md.append("\n## Mesh scenes: BVH, threads, and Mitsuba 3 on the same file\n\n")
                .append("| scene | primitives | size, samples | load | linear (2 threads) | BVH, 1 thread | BVH, 2 threads | 1 → 2 threads | Mitsuba 3 scalar_rgb, 2 threads | ray1 / Mitsuba |\n")
                .append("|---|---|---|---|---|---|---|---|---|---|\n");
        for (Path file : MeshScenes.writeAll(out.resolve("mesh-scenes"))) {
            long start = System.nanoTime();
            Scene scene = SceneLoader.load(file);
            double load = (System.nanoTime() - start) / 1e9;
            RenderPlan plan = RenderPlan.of(scene);
            Timed two = time(plan, 2, 2, 5);
            Timed one = time(plan, 1, 1, 3);
            String name = SceneFiles.nameOf(file);
            // The linear loop over 81,920 triangles takes minutes at 16 samples: one render at 1 sample, scaled.
            boolean big = name.startsWith("bumpy");
            RenderPlan linearPlan = big ? RenderPlan.of(scene, 1).withAcceleration(Acceleration.NONE)
                    : plan.withAcceleration(Acceleration.NONE);
            Timed linear = time(linearPlan, 2, big ? 0 : 1, big ? 1 : 2);
            double linearSeconds = linear.seconds * (big ? plan.gridSide() * plan.gridSide() : 1);
            Double mitsuba = mitsuba(python, file);
            md.append(String.format(Locale.ROOT, "| %s | %,d | %dx%d, %d | %s | %s%s | %s | %s | %.2f | %s | %s |%n", name, plan.primitives(),
                    scene.getWidth(), scene.getHeight(), plan.gridSide() * plan.gridSide(), ms(load), ms(linearSeconds),
                    big ? " (1 sample × 16)" : "", ms(one.seconds), ms(two.seconds), one.seconds / two.seconds,
                    mitsuba == null ? "not installed" : ms(mitsuba), mitsuba == null ? "–" : String.format(Locale.ROOT, "%.2f", two.seconds / mitsuba)));
            System.out.println("mesh " + name + ": " + ms(two.seconds) + " bvh on 2 threads; mitsuba " + mitsuba);
        }
        Path report = out.resolve("acceleration.md");
        Files.write(report, md.toString().getBytes(StandardCharsets.UTF_8));
        System.out.println(md);
        System.out.println("Report: " + report);
    }

    private static final class Timed {
        final double seconds;
        final RenderResult result;

        Timed(double seconds, RenderResult result) {
            this.seconds = seconds;
            this.result = result;
        }
    }

    /** The best render time of {@code runs} renders after {@code warmUp} renders. */
    private static Timed time(RenderPlan plan, int threads, int warmUp, int runs) {
        for (int k = 0; k < warmUp; k++) {
            new Renderer(plan, threads).render();
        }
        double best = Double.POSITIVE_INFINITY;
        RenderResult last = null;
        for (int k = 0; k < runs; k++) {
            last = new Renderer(plan, threads).render();
            best = Math.min(best, last.seconds);
        }
        return new Timed(best, last);
    }

    /** Mitsuba's best render time for the scene on every core, or null when Python cannot run it. */
    private static Double mitsuba(String python, Path scene) {
        try {
            Process process = new ProcessBuilder(python, "src/instructorBench/mitsuba/render_mitsuba.py", scene.toString(), "--repeat", "5")
                    .redirectError(ProcessBuilder.Redirect.DISCARD).start();
            String last = null;
            try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
                for (String line = in.readLine(); line != null; line = in.readLine()) {
                    last = line;
                }
            }
            if (process.waitFor() != 0 || last == null) {
                return null;
            }
            Map<?, ?> json = new Gson().fromJson(last, Map.class);
            return ((Number) json.get("render_seconds_best")).doubleValue();
        } catch (IOException | RuntimeException e) {
            return null;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        }
    }

    private static String ms(double seconds) {
        return seconds >= 1 ? String.format(Locale.ROOT, "%.2f s", seconds) : String.format(Locale.ROOT, "%.1f ms", seconds * 1000);
    }
}
