package ray.cli;

import com.google.gson.GsonBuilder;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import ray.render.RenderResult;
import ray.scene.Scene;

/** The figures of one rendered scene, as printed and as written by {@code --stats}. */
final class SceneStats {
    String scene;
    int width;
    int height;
    int samples;
    /** "grid" or "jittered (seed S)": where each pixel's samples fall. */
    String sampling;
    int threads;
    double seconds;
    List<String> effects;
    List<String> skipped;
    Map<String, Long> rays;
    /** "bvh", "student" or "none": how the searches ran. */
    String acceleration;
    /** Ray–primitive intersection tests as counted, in all and per kind of ray. */
    long intersectionTests;
    Map<String, Long> intersectionTestsByRay;
    /** Bounding boxes tested (BVH nodes visited, placed groups' boxes), in all and per kind of ray. */
    long boxTests;
    Map<String, Long> boxTestsByRay;
    long specularEvaluations;
    long textureLookups;
    /** The plan line, printed under the summary; not in the JSON (effects and skipped hold it). */
    transient String planLine;

    static SceneStats of(String name, Scene scene, RenderResult result) {
        SceneStats s = new SceneStats();
        s.scene = name;
        s.width = scene.getWidth();
        s.height = scene.getHeight();
        s.samples = result.samplesPerPixel;
        s.sampling = result.plan.pattern().describe();
        s.threads = result.threads;
        s.seconds = result.seconds;
        s.effects = result.plan.effects();
        s.skipped = result.plan.skipped();
        s.rays = result.rays.byKind();
        s.acceleration = result.plan.acceleration().option();
        s.intersectionTests = result.rays.totalIntersectionTests();
        s.intersectionTestsByRay = result.rays.byKind(result.rays.intersectionTests);
        s.boxTests = result.rays.totalBoxTests();
        s.boxTestsByRay = result.rays.byKind(result.rays.boxTests);
        s.specularEvaluations = result.rays.specular;
        s.textureLookups = result.rays.textureLookups;
        s.planLine = result.plan.describe();
        return s;
    }

    String summaryLine() {
        long total = rays.values().stream().mapToLong(Long::longValue).sum();
        StringBuilder kinds = new StringBuilder();
        rays.forEach((kind, count) -> kinds.append(kinds.length() == 0 ? "" : ", ").append(kind).append(' ').append(count));
        return String.format(java.util.Locale.ROOT, "%-24s %5dx%-5d %7.2f s  %,12d rays (%s)", scene, width, height, seconds, total, kinds);
    }

    /** The line under the summary: which effects ran and which were skipped, indented. */
    String planLine() {
        return "  " + planLine;
    }

    static void writeJson(List<SceneStats> stats, Path file) throws IOException {
        String json = new GsonBuilder().setPrettyPrinting().create().toJson(stats);
        Path parent = file.toAbsolutePath().getParent();
        Files.createDirectories(parent);
        Path temporary = Files.createTempFile(parent, "." + file.getFileName(), ".tmp");
        try {
            Files.writeString(temporary, json + "\n", StandardCharsets.UTF_8);
            Files.move(temporary, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        } finally {
            Files.deleteIfExists(temporary);
        }
    }
}
