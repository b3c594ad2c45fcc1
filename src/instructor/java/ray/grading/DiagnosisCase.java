package ray.grading;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import ray.grading.VariantFolders.Variant;

/**
 * One submission the diagnosis evaluation grades, and the mistakes it makes: a known-wrong variant
 * (its own), a correct variant (none), or a held-out attempt (the variants its {@code mistakes} file
 * lists, one folder name a line).
 */
final class DiagnosisCase {
    /** Where the held-out attempts live: each a folder of student files and a {@code mistakes} file. */
    static final String ATTEMPTS = "src/instructorTest/attempts";

    enum Kind { WRONG, CORRECT, ATTEMPT }

    final String name;
    final Kind kind;
    /** The task graded (a variant's); null: all of them (an attempt is a whole submission). */
    final Integer task;
    private final List<Path> sources;
    /** The variants (folder names) whose mistakes this code makes: the names the feedback may give. */
    final Set<String> makes;

    private DiagnosisCase(String name, Kind kind, Integer task, List<Path> sources, Set<String> makes) {
        this.name = name;
        this.kind = kind;
        this.task = task;
        this.sources = sources;
        this.makes = makes;
    }

    static DiagnosisCase of(Variant v) {
        String name = v.folder.getFileName().toString();
        return v.knownWrong != null ? new DiagnosisCase(name, Kind.WRONG, v.task, v.sources, Set.of(name))
                : new DiagnosisCase(name, Kind.CORRECT, v.task, v.sources, Set.of());
    }

    /** The held-out attempts of {@code project}, each checked to list only variants that exist. */
    static List<DiagnosisCase> attempts(Path project, Set<String> knownWrong) throws IOException {
        Path root = project.resolve(ATTEMPTS);
        List<DiagnosisCase> attempts = new ArrayList<>();
        if (!Files.isDirectory(root)) {
            return attempts;
        }
        List<Path> folders;
        try (Stream<Path> list = Files.list(root)) {
            folders = list.filter(Files::isDirectory).sorted().collect(Collectors.toList());
        }
        for (Path folder : folders) {
            Path list = folder.resolve("mistakes");
            Set<String> makes = new LinkedHashSet<>();
            int number = 0;
            for (String line : Files.readAllLines(list, StandardCharsets.UTF_8)) {
                number++;
                String variant = line.replaceFirst("#.*", "").strip();
                if (variant.isEmpty()) {
                    continue;
                }
                if (!knownWrong.contains(variant)) {
                    throw new IllegalArgumentException(project.relativize(list) + " line " + number + ": no known-wrong variant named "
                            + variant + "; expected a folder of " + VariantFolders.VARIANTS);
                }
                makes.add(variant);
            }
            List<Path> sources;
            try (Stream<Path> files = Files.list(folder)) {
                sources = files.filter(p -> p.toString().endsWith(".java")).sorted().collect(Collectors.toList());
            }
            attempts.add(new DiagnosisCase("attempt " + folder.getFileName(), Kind.ATTEMPT, null, sources, makes));
        }
        return attempts;
    }

    /**
     * The case's files, side by side in {@code folder} (a flat submission, as a student uploads one).
     * A variant replaces some of the solution's files (a texture variant may hold RepeatTexture only),
     * so its submission is the solution's files of {@code project} (its {@code studentFiles}) with the
     * variant's in their place; an attempt is handed in as it is.
     */
    Path submissionIn(Path folder, Path project, Set<String> studentFiles) throws IOException {
        Files.createDirectories(folder);
        if (kind != Kind.ATTEMPT) {
            for (String file : studentFiles) {
                Files.copy(project.resolve(file), folder.resolve(Path.of(file).getFileName().toString()), StandardCopyOption.REPLACE_EXISTING);
            }
        }
        for (Path source : sources) {
            Files.copy(source, folder.resolve(source.getFileName().toString()), StandardCopyOption.REPLACE_EXISTING);
        }
        return folder;
    }

    /**
     * What the feedback named, judged against what this code does: each known mistake (folder →
     * description) whose name appears in a failed test's output, by a render match or by the unit
     * tests' failures.
     */
    DiagnosisRow judge(GradedFeedback feedback, Map<String, String> mistakeOf) {
        Set<String> named = new LinkedHashSet<>();
        Set<String> where = new LinkedHashSet<>();
        boolean picture = false;
        int renders = 0;
        int rendersNamed = 0;
        for (GradedFeedback.Failed failed : feedback.failed()) {
            boolean namedHere = false;
            for (Map.Entry<String, String> mistake : mistakeOf.entrySet()) {
                boolean byRender = failed.output().contains(VariantMistakes.MATCHES + mistake.getValue());
                boolean byTests = failed.output().contains(FailureSignatures.SAME_FAILURES + mistake.getValue())
                        || failed.output().contains(FailureSignatures.ONE_OF_TWO + mistake.getValue());
                if (byRender || byTests) {
                    named.add(mistake.getKey());
                    where.add(byRender ? "render" : "unit tests");
                    namedHere |= makes.contains(mistake.getKey());
                }
            }
            boolean flipped = failed.output().contains(KnownMistakes.ADVICE_START);
            picture |= flipped;
            if (failed.isDifferingRender()) {
                renders++;
                rendersNamed += namedHere || flipped ? 1 : 0;
            }
        }
        Set<String> wrong = new LinkedHashSet<>(named);
        wrong.removeAll(makes);
        Set<String> right = new LinkedHashSet<>(named);
        right.retainAll(makes);
        return new DiagnosisRow(this, feedback, right, wrong, where, picture, renders, rendersNamed);
    }
}
