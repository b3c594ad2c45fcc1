package ray.bench;

import com.google.gson.Gson;
import com.google.gson.reflect.TypeToken;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The tables of docs/performance.md, in Markdown, from the files {@link BenchMain} writes. Every
 * ratio divides two numbers of the same run. A figure whose benchmark did not run shows as "–".
 */
final class BenchReport {
    /** Effect present vs absent: {effect, scene with it, scene without it}. */
    private static final String[][] EFFECT_PAIRS = {
            {"lighting + shadows (2 lights)", "lit", "unlit"},
            {"specular (Phong)", "phong", "lit"},
            {"reflection (Glazed spheres)", "glazed", "lit"},
            {"antialiasing (2×2 samples)", "antialiased", "lit"},
            {"transforms (a rotated group)", "transformed", "lit"},
            {"vertex normals (576-triangle torus)", "scenes/mesh-smooth.xml", "scenes/mesh-flat.xml"},
    };

    private final List<Map<String, Object>> jmh;
    private final Map<String, Map<String, Object>> scenes;
    private final List<Map<String, Object>> memory;
    private final Path out;
    private final StringBuilder md = new StringBuilder();

    private BenchReport(Path out) throws IOException {
        this.out = out;
        jmh = read(out.resolve("jmh.json"), new TypeToken<List<Map<String, Object>>>() { });
        scenes = read(out.resolve("scenes.json"), new TypeToken<Map<String, Map<String, Object>>>() { });
        memory = read(out.resolve("memory.json"), new TypeToken<List<Map<String, Object>>>() { });
    }

    static String markdown(Path out) throws IOException {
        BenchReport r = new BenchReport(out);
        r.machine();
        r.intersection();
        r.threads();
        r.effects();
        r.noEffect();
        r.anchor();
        r.perScene();
        r.mesh();
        return r.md.toString();
    }

    private void machine() throws IOException {
        String cpu = "unknown CPU";
        Path cpuinfo = Path.of("/proc/cpuinfo");
        if (Files.isReadable(cpuinfo)) {
            for (String line : Files.readAllLines(cpuinfo)) {
                if (line.startsWith("model name")) {
                    cpu = line.substring(line.indexOf(':') + 1).trim();
                    break;
                }
            }
        }
        md.append("Machine: ").append(cpu).append(", ").append(Runtime.getRuntime().availableProcessors())
                .append(" cores, ").append(System.getProperty("java.vm.name")).append(' ')
                .append(System.getProperty("java.runtime.version")).append(", ")
                .append(System.getProperty("os.name")).append(' ').append(System.getProperty("os.version")).append(".\n\n");
    }

    private void intersection() {
        md.append("| primitive | one test | tests/s per core | Group, per test | Surface[] loop | flat arrays"
                + " | Group vs Surface[] | Group vs flat | allocated per test |\n|---|---|---|---|---|---|---|---|---|\n");
        for (String p : new String[] {"sphere", "triangle"}) {
            double each = score("IntersectionBench.eachTest", "primitive", p);
            double group = score("IntersectionBench.group", "primitive", p);
            double array = score("IntersectionBench.array", "primitive", p);
            double flat = score("IntersectionBench.flat", "primitive", p);
            double alloc = metric("IntersectionBench.group", "gc.alloc.rate.norm", "primitive", p);
            md.append(row(p, ns(each), fmt("%.0f M", 1e3 / each), ns(group), ns(array), ns(flat),
                    fmt("%.2f", array / group), fmt("%.2f", flat / group), fmt("%.2f B", alloc)));
        }
        md.append('\n');
    }

    private void threads() {
        md.append("| scene | 1 thread | 2 threads | speedup |\n|---|---|---|---|\n");
        for (String scene : scenes.keySet()) {
            if (scene.contains("bench")) {
                continue;
            }
            double one = renderMs(scene, 1);
            double two = renderMs(scene, 2);
            md.append(row(name(scene), ms(one), ms(two), fmt("%.2f", one / two)));
        }
        md.append('\n');
    }

    private void effects() {
        md.append("| effect | with it (1 thread) | without it | ratio |\n|---|---|---|---|\n");
        for (String[] pair : EFFECT_PAIRS) {
            double with = renderMs(variant(pair[1]), 1);
            double without = renderMs(variant(pair[2]), 1);
            md.append(row(pair[0], withError(variant(pair[1])) + " (" + name(pair[1]) + ")",
                    withError(variant(pair[2])) + " (" + name(pair[2]) + ")", fmt("%.2f", with / without)));
        }
        md.append('\n');
    }

    private void noEffect() {
        double framework = score("NoEffectBench.framework");
        double bare = score("NoEffectBench.bareLoop");
        md.append("| no-effect scene (normals, 1 thread) | bare camera + closest-hit loop | ratio |\n|---|---|---|\n");
        md.append(row(ms(framework), ms(bare), fmt("%.3f", framework / bare))).append('\n');
    }

    /** Camera samples per second on every core for the scene the Mitsuba 3 anchor describes. */
    private void anchor() {
        md.append("| scene (160×120, 26 primitives, 2 point lights, shadows) | samples per pixel | time (2 threads) | samples/s |\n"
                + "|---|---|---|---|\n");
        for (String[] v : new String[][] {{"lit", "1"}, {"antialiased", "4"}}) {
            double time = renderMs(variant(v[0]), 2);
            md.append(row("bench: " + v[0], v[1], ms(time), fmt("%.2f M", 160 * 120 * Double.parseDouble(v[1]) / time / 1e3)));
        }
        md.append('\n');
    }

    private void perScene() {
        md.append("| scene | plan | pixels | rays | time (2 threads) | rays/s | allocated per ray | live heap | peak heap |\n"
                + "|---|---|---|---|---|---|---|---|---|\n");
        for (Map.Entry<String, Map<String, Object>> e : scenes.entrySet()) {
            String scene = e.getKey();
            Map<String, Object> facts = e.getValue();
            double rays = ((Number) facts.get("totalRays")).doubleValue();
            double time = renderMs(scene, 2);
            double alloc = metric("RenderBench.render", "gc.alloc.rate.norm", "scene", scene, "threads", "2");
            Map<String, Object> mem = memoryOf(scene);
            md.append(row(name(scene), String.valueOf(facts.get("plan")).replace("effects: ", ""),
                    fmt("%.0f×%.0f", num(facts.get("width")), num(facts.get("height"))), fmt("%,.0f", rays),
                    ms(time), fmt("%.1f M", rays / time / 1e3), fmt("%.0f B", alloc / rays),
                    mem == null ? "–" : fmt("%.1f MB", num(mem.get("liveBytes")) / 1e6),
                    mem == null ? "–" : fmt("%.0f MB", num(mem.get("peakHeapBytes")) / 1e6)));
        }
        md.append('\n');
    }

    private void mesh() {
        Map<String, Object> m = memoryOf(null);
        md.append("| mesh | triangles | load, first in a JVM | load, best of 3 | bytes per triangle | of which flat arrays |\n"
                + "|---|---|---|---|---|---|\n");
        if (m != null) {
            md.append(row(out.relativize(Path.of(String.valueOf(m.get("file")))).toString(), fmt("%,.0f", num(m.get("triangles"))),
                    fmt("%.2f s", num(m.get("coldLoadSeconds"))), fmt("%.2f s", num(m.get("bestLoadSeconds"))),
                    fmt("%.0f", num(m.get("bytesPerTriangle"))), fmt("%.0f", num(m.get("arrayBytesPerTriangle")))));
        }
        md.append('\n');
    }

    // ---- lookups ----

    private double renderMs(String scene, int threads) {
        return score("RenderBench.render", "scene", scene, "threads", String.valueOf(threads));
    }

    /** One thread's render time with JMH's 99.9% confidence half-width. */
    private String withError(String scene) {
        Map<String, Object> r = find("RenderBench.render", "scene", scene, "threads", "1");
        if (r == null) {
            return "–";
        }
        Map<?, ?> m = (Map<?, ?>) r.get("primaryMetric");
        return fmt("%.2f ± %.2f ms", num(m.get("score")), num(m.get("scoreError")));
    }

    private String variant(String name) {
        return name.contains("/") ? name : out.resolve("scenes").resolve(name + ".xml").toString();
    }

    private double score(String benchmark, String... params) {
        Map<String, Object> r = find(benchmark, params);
        return r == null ? Double.NaN : num(((Map<?, ?>) r.get("primaryMetric")).get("score"));
    }

    private double metric(String benchmark, String metric, String... params) {
        Map<String, Object> r = find(benchmark, params);
        Object secondary = r == null ? null : ((Map<?, ?>) r.get("secondaryMetrics")).get(metric);
        return secondary == null ? Double.NaN : num(((Map<?, ?>) secondary).get("score"));
    }

    private Map<String, Object> find(String benchmark, String... params) {
        for (Map<String, Object> r : jmh) {
            if (!String.valueOf(r.get("benchmark")).endsWith(benchmark)) {
                continue;
            }
            Map<?, ?> p = r.get("params") == null ? Collections.emptyMap() : (Map<?, ?>) r.get("params");
            boolean match = true;
            for (int k = 0; k < params.length; k += 2) {
                match &= params[k + 1].equals(String.valueOf(p.get(params[k])));
            }
            if (match) {
                return r;
            }
        }
        return null;
    }

    private Map<String, Object> memoryOf(String scene) {
        for (Map<String, Object> m : memory) {
            if (scene == null ? m.containsKey("triangles") : scene.equals(m.get("scene"))) {
                return m;
            }
        }
        return null;
    }

    private static <T> T read(Path file, TypeToken<T> type) throws IOException {
        if (!Files.exists(file)) {
            return new Gson().fromJson(type.getRawType() == Map.class ? "{}" : "[]", type.getType());
        }
        return new Gson().fromJson(Files.readString(file, StandardCharsets.UTF_8), type.getType());
    }

    private static String name(String scene) {
        return scene.replaceFirst("^scenes/", "").replaceFirst("^.*bench/scenes/", "bench: ").replaceFirst("\\.xml$", "");
    }

    private static double num(Object o) {
        return o == null ? Double.NaN : ((Number) o).doubleValue();
    }

    private static String ns(double x) {
        return fmt("%.2f ns", x);
    }

    private static String ms(double x) {
        return x < 10 ? fmt("%.2f ms", x) : fmt("%.0f ms", x);
    }

    private static String fmt(String format, double... values) {
        for (double v : values) {
            if (Double.isNaN(v)) {
                return "–";
            }
        }
        Object[] boxed = new Object[values.length];
        for (int k = 0; k < values.length; k++) {
            boxed[k] = values[k];
        }
        return String.format(Locale.ROOT, format, boxed);
    }

    private static String row(String... cells) {
        return "| " + String.join(" | ", cells) + " |\n";
    }
}
