package ray.grading;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * The instructor's other versions of the student files (src/instructorTest/variants): each folder
 * holds one way of writing a task's files, laid out as under src/main/java. A variant whose class
 * comment says "Known wrong: what it does" is a known mistake (the grader names it when a render
 * matches, {@link VariantMistakes}); the others are correct alternatives. The made-up class of
 * {@code gradle sampleClass} draws from both.
 */
public final class VariantFolders {
    public static final String VARIANTS = "src/instructorTest/variants";
    private static final Pattern KNOWN_WRONG = Pattern.compile("Known wrong: (.*?)\\s*\\*/", Pattern.DOTALL);

    /** One variant: its folder, its Java files (sorted), the task they belong to, and what it does wrong (null when correct). */
    public static final class Variant {
        public final Path folder;
        public final List<Path> sources;
        public final int task;
        public final String knownWrong;

        private Variant(Path folder, List<Path> sources, int task, String knownWrong) {
            this.folder = folder;
            this.sources = sources;
            this.task = task;
            this.knownWrong = knownWrong;
        }

        /** The student file a source stands for, e.g. "src/main/java/ray/surface/Sphere.java". */
        public String studentFile(Path source) {
            return studentFileOf(folder, source);
        }
    }

    private VariantFolders() {
    }

    private static String studentFileOf(Path folder, Path source) {
        return "src/main/java/" + folder.relativize(source).toString().replace('\\', '/');
    }

    /**
     * Every variant of {@code tree} whose files are student files, sorted by folder name; its task is
     * that of its files, its description the first "Known wrong:" comment among them (in file order).
     */
    public static List<Variant> in(Path tree, Map<String, Integer> studentFiles) throws IOException {
        Path root = tree.resolve(VARIANTS);
        List<Variant> variants = new ArrayList<>();
        if (!Files.isDirectory(root)) {
            return variants;
        }
        List<Path> folders;
        try (Stream<Path> list = Files.list(root)) {
            folders = list.filter(Files::isDirectory).sorted().collect(Collectors.toList());
        }
        for (Path folder : folders) {
            List<Path> sources;
            try (Stream<Path> walk = Files.walk(folder)) {
                sources = walk.filter(p -> p.toString().endsWith(".java")).sorted().collect(Collectors.toList());
            }
            Integer task = null;
            String description = null;
            for (Path source : sources) {
                task = task != null ? task : studentFiles.get(studentFileOf(folder, source));
                Matcher m = KNOWN_WRONG.matcher(Files.readString(source, StandardCharsets.UTF_8));
                if (description == null && m.find()) {
                    description = m.group(1).replaceAll("\\s*\\n\\s*\\*?\\s*", " ");
                }
            }
            if (task != null) {
                variants.add(new Variant(folder, sources, task, description));
            }
        }
        return variants;
    }
}
