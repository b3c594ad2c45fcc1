package ray.tools;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import ray.grading.ClassSubmission;
import ray.grading.SolutionMarkers;
import ray.grading.StudentFiles;
import ray.grading.VariantFolders;
import ray.grading.VariantFolders.Variant;

/**
 * A made-up class for trying {@code gradeAll} before the real one hands in ({@code gradle sampleClass
 * -Pcount=N -Pout=DIR [-Pseed=S]}): N submissions in the layout of Gradescope's "Export Submissions"
 * (a folder {@code submission_K} of flat files each, as Gradescope keeps uploads, and
 * {@code submission_metadata.yml} naming each one's student). Each task of each submission is, by a
 * seeded draw, the solution (60 %), one of the task's correct alternative solutions (15 %), one of
 * its known mistakes (15 %), or the untouched stub (10 %); both from src/instructorTest/variants, so
 * the class exercises every way of being right and wrong that the grader knows.
 */
public final class SampleClass {
    private SampleClass() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length < 3) {
            System.err.println("usage: SampleClass PROJECT OUT_DIR COUNT [SEED]");
            System.exit(2);
        }
        Path project = Path.of(args[0]);
        Path out = Path.of(args[1]);
        int count;
        long seed;
        try {
            count = Integer.parseInt(args[2]);
            seed = args.length > 3 ? Long.parseLong(args[3]) : 1;
        } catch (NumberFormatException e) {
            System.err.println("error: -Pcount and -Pseed must be whole numbers, but were " + args[2]
                    + (args.length > 3 ? " and " + args[3] : ""));
            System.exit(2);
            return;
        }
        if (count < 1) {
            System.err.println("error: -Pcount must be at least 1, but was " + count);
            System.exit(2);
        }
        if (Files.exists(out) && !isEmptyFolder(out)) {
            System.err.println("error: " + out + " is not empty; give -Pout a new folder");
            System.exit(2);
        }
        Map<Integer, Integer> drawn = write(project, out, count, seed);
        System.out.println("sample class: " + count + " submissions in " + out + " (tasks drawn: " + drawn.get(0)
                + " solution, " + drawn.get(1) + " correct alternative, " + drawn.get(2) + " known mistake, "
                + drawn.get(3) + " stub); grade them with gradle gradeAll -Psubmissions=" + out);
    }

    /**
     * Writes the class into {@code out} and returns how many tasks were drawn of each kind (0 solution,
     * 1 correct alternative, 2 known mistake, 3 stub); the same seed writes the same class.
     */
    public static Map<Integer, Integer> write(Path project, Path out, int count, long seed) throws IOException {
        Map<String, Integer> studentFiles = StudentFiles.in(project);
        Map<Integer, List<Variant>> correct = new TreeMap<>();
        Map<Integer, List<Variant>> wrong = new TreeMap<>();
        for (Variant variant : VariantFolders.in(project, studentFiles)) {
            (variant.knownWrong != null ? wrong : correct).computeIfAbsent(variant.task, t -> new ArrayList<>()).add(variant);
        }
        Random random = new Random(seed);
        Map<Integer, Integer> drawn = new TreeMap<>(Map.of(0, 0, 1, 0, 2, 0, 3, 0));
        StringBuilder metadata = new StringBuilder();
        Files.createDirectories(out);
        for (int k = 1; k <= count; k++) {
            String id = String.format("submission_%03d", k);
            Path folder = out.resolve(id);
            Files.createDirectories(folder);
            Map<String, String> files = new TreeMap<>();
            for (Map.Entry<String, Integer> file : studentFiles.entrySet()) {
                files.put(file.getKey(), Files.readString(project.resolve(file.getKey()), StandardCharsets.UTF_8));
            }
            for (int task : studentFiles.values().stream().distinct().sorted().collect(Collectors.toList())) {
                double draw = random.nextDouble();
                int kind = draw < 0.60 ? 0 : draw < 0.75 ? 1 : draw < 0.90 ? 2 : 3;
                List<Variant> choices = kind == 1 ? correct.get(task) : kind == 2 ? wrong.get(task) : null;
                if ((kind == 1 || kind == 2) && (choices == null || choices.isEmpty())) {
                    kind = 0;
                }
                drawn.merge(kind, 1, Integer::sum);
                if (kind == 3) {
                    for (Map.Entry<String, Integer> file : studentFiles.entrySet()) {
                        if (file.getValue() == task) {
                            files.put(file.getKey(), SolutionMarkers.studentVersion(files.get(file.getKey()), file.getKey()));
                        }
                    }
                } else if (choices != null && kind != 0) {
                    Variant variant = choices.get(random.nextInt(choices.size()));
                    for (Path source : variant.sources) {
                        files.put(variant.studentFile(source), Files.readString(source, StandardCharsets.UTF_8));
                    }
                }
            }
            for (Map.Entry<String, String> file : files.entrySet()) {
                Files.writeString(folder.resolve(Path.of(file.getKey()).getFileName().toString()), file.getValue(), StandardCharsets.UTF_8);
            }
            metadata.append(id).append(":\n")
                    .append("  :submitters:\n")
                    .append(String.format("  - :name: Student %03d\n", k))
                    .append(String.format("    :sid: '%05d'\n", 10000 + k))
                    .append(String.format("    :email: student%03d@example.edu\n", k));
        }
        Files.writeString(out.resolve(ClassSubmission.METADATA), metadata.toString(), StandardCharsets.UTF_8);
        return drawn;
    }

    private static boolean isEmptyFolder(Path folder) throws IOException {
        if (!Files.isDirectory(folder)) {
            return false;
        }
        try (Stream<Path> list = Files.list(folder)) {
            return list.findAny().isEmpty();
        }
    }
}
