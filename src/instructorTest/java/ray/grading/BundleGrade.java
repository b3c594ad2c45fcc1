package ray.grading;

import static org.junit.Assert.assertEquals;

import com.google.gson.Gson;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import ray.tools.AutograderBundle;
import ray.tools.KitInputs;

/**
 * One submission graded as Gradescope grades it, for the attack tests: the real bundle of the
 * current assignment built into {@code root} (root's alone), the student files of this checkout each
 * changed by {@code change} (by its project path), run_autograder run as the platform runs it, and
 * results.json read back with the seconds it took.
 */
final class BundleGrade {
    final Map<String, Object> results;
    final double seconds;

    private BundleGrade(Map<String, Object> results, double seconds) {
        this.results = results;
        this.seconds = seconds;
    }

    /** Grades the submission whose files are this checkout's student files, each as {@code change} gives it for its path. */
    static BundleGrade of(Path checkout, Path root, java.util.function.BiFunction<String, String, String> change) throws Exception {
        Files.setPosixFilePermissions(root, PosixFilePermissions.fromString("rwx------"));
        Path bundle = root.resolve("ray1-gradescope.zip");
        KitInputs kit = new KitInputs();
        AutograderBundle.build(checkout, bundle, kit.classes, kit.libraries);
        KitInputs.unpack(bundle, root.resolve("source"));
        Path submission = root.resolve("submission");
        Files.createDirectories(submission);
        for (String file : StudentFiles.in(checkout).keySet()) {
            String source = change.apply(file, Files.readString(checkout.resolve(file), StandardCharsets.UTF_8));
            Files.writeString(submission.resolve(Path.of(file).getFileName().toString()), source, StandardCharsets.UTF_8);
        }
        Map<String, String> variables = new LinkedHashMap<>();
        variables.put("AUTOGRADER_ROOT", root.toString());
        long start = System.nanoTime();
        assertEquals(0, KitInputs.runScript(root.resolve("source/run_autograder"), variables, root.resolve("run.log")));
        double seconds = (System.nanoTime() - start) / 1e9;
        @SuppressWarnings("unchecked")
        Map<String, Object> read = new Gson().fromJson(Files.readString(root.resolve("results/results.json"), StandardCharsets.UTF_8), Map.class);
        return new BundleGrade(read, seconds);
    }

    @SuppressWarnings("unchecked")
    List<Map<String, Object>> tests() {
        return (List<Map<String, Object>>) results.get("tests");
    }
}
