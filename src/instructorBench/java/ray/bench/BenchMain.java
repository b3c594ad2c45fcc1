package ray.bench;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
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
import java.util.Map;
import org.openjdk.jmh.profile.GCProfiler;
import org.openjdk.jmh.results.format.ResultFormatType;
import org.openjdk.jmh.runner.Runner;
import org.openjdk.jmh.runner.options.CommandLineOptions;
import org.openjdk.jmh.runner.options.OptionsBuilder;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.scene.SceneFiles;
import ray.scene.SceneLoader;

/**
 * {@code gradle bench}: everything behind docs/performance.md, in four steps, all under OUT
 * (build/bench):
 * <ol>
 * <li>{@code scenes.json}: each benchmarked scene's plan and ray counts (fixed by the scene);</li>
 * <li>{@code jmh.json}: the JMH benchmarks ({@link IntersectionBench}, {@link RenderBench} over
 * every scene at 1 and 2 threads, {@link NoEffectBench}), with JMH's allocation profiler;</li>
 * <li>{@code memory.json}: {@link MemoryProbe} per scene and for the 1M-triangle mesh, each in a
 * fresh JVM with the serial collector and a heap that starts small;</li>
 * <li>{@code report.md}: the tables ({@link BenchReport}).</li>
 * </ol>
 * {@code -Pjmh='OPTIONS'} passes JMH options (e.g. a benchmark regexp, {@code -f 1 -i 3}) and
 * skips the memory probes; the report then uses whatever results exist.
 */
public final class BenchMain {
    public static void main(String[] args) throws Exception {
        Path out = Paths.get(args[0]);
        String jmhOptions = args.length > 2 && args[1].equals("--jmh") ? args[2].trim() : null;
        Files.createDirectories(out);
        Path variants = out.resolve("scenes");
        EffectScenes.writeAll(variants);
        List<Path> scenes = new ArrayList<>(SceneFiles.under(Paths.get("scenes"), Paths.get("scenes", "reference")));
        scenes.addAll(SceneFiles.under(variants));

        Map<String, Object> facts = new LinkedHashMap<>();
        for (Path scene : scenes) {
            facts.put(scene.toString(), sceneFacts(scene));
        }
        write(out.resolve("scenes.json"), facts);

        OptionsBuilder options = new OptionsBuilder();
        if (jmhOptions != null) {
            options.parent(new CommandLineOptions(jmhOptions.split("\\s+")));
        } else {
            options.include("ray\\.bench\\..*");
        }
        if (jmhOptions == null || !jmhOptions.contains("scene=")) {
            options.param("scene", scenes.stream().map(Path::toString).toArray(String[]::new));
        }
        options.addProfiler(GCProfiler.class)
                .resultFormat(ResultFormatType.JSON)
                .result(out.resolve("jmh.json").toString());
        new Runner(options.build()).run();

        if (jmhOptions == null) {
            List<Object> memory = new ArrayList<>();
            for (Path scene : scenes) {
                memory.add(probe("scene", scene.toString()));
            }
            memory.add(probe("mesh", out.toString()));
            write(out.resolve("memory.json"), memory);
        }
        Path report = out.resolve("report.md");
        Files.write(report, BenchReport.markdown(out).getBytes(StandardCharsets.UTF_8));
        System.out.println("Report: " + report);
    }

    /** The plan and the ray counts of one render on every core. */
    private static Map<String, Object> sceneFacts(Path scene) {
        RenderResult r = new Renderer(SceneLoader.load(scene), 0, 0).render();
        Map<String, Object> facts = new LinkedHashMap<>();
        facts.put("plan", r.plan.describe());
        facts.put("width", r.image.width());
        facts.put("height", r.image.height());
        facts.put("primitives", r.plan.primitives());
        facts.put("rays", r.rays.byKind());
        facts.put("totalRays", r.rays.total());
        return facts;
    }

    private static Object probe(String kind, String argument) throws IOException, InterruptedException {
        Path java = Paths.get(System.getProperty("java.home"), "bin", "java");
        Process process = new ProcessBuilder(java.toString(), "-XX:+UseSerialGC", "-Xms8m", "-Xmx6g",
                "-cp", System.getProperty("java.class.path"), MemoryProbe.class.getName(), kind, argument)
                .redirectError(ProcessBuilder.Redirect.INHERIT).start();
        String line;
        try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
            line = in.readLine();
        }
        if (process.waitFor() != 0 || line == null) {
            throw new IllegalStateException("memory probe failed: " + kind + " " + argument);
        }
        System.out.println("memory " + kind + " " + argument + ": " + line);
        return new Gson().fromJson(line, Object.class);
    }

    private static void write(Path file, Object value) throws IOException {
        Gson gson = new GsonBuilder().setPrettyPrinting().create();
        Files.write(file, gson.toJson(value).getBytes(StandardCharsets.UTF_8));
    }
}
