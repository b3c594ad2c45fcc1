package ray.grading;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * One submission of a class's folder: a subfolder or a .zip, named by its id (the folder's name,
 * or the zip's without ".zip"), with its students when Gradescope's export names them.
 */
public record ClassSubmission(String id, Path path, List<Submitter> submitters) {
    /** The export's file of who submitted what, beside the submission folders. */
    public static final String METADATA = "submission_metadata.yml";

    /**
     * Every submission in {@code dir}, sorted by id; {@code skip} (the output folder, when it is
     * inside) and hidden entries are not submissions.
     *
     * @throws IllegalArgumentException with a one-line message when dir is missing or holds none
     */
    public static List<ClassSubmission> in(Path dir, Path skip) throws IOException {
        if (!Files.isDirectory(dir)) {
            throw new IllegalArgumentException(dir + " is not a folder of submissions");
        }
        Map<String, List<Submitter>> metadata = GradescopeMetadata.read(dir.resolve(METADATA));
        List<ClassSubmission> found = new ArrayList<>();
        try (Stream<Path> entries = Files.list(dir)) {
            for (Path p : entries.sorted().collect(Collectors.toList())) {
                String name = p.getFileName().toString();
                boolean zip = Files.isRegularFile(p) && name.toLowerCase().endsWith(".zip");
                if (name.startsWith(".") || name.equals("__MACOSX") || sameFile(p, skip) || !(zip || Files.isDirectory(p))) {
                    continue;
                }
                String id = zip ? name.substring(0, name.length() - 4) : name;
                found.add(new ClassSubmission(id, p, metadata.getOrDefault(id, metadata.getOrDefault(name, List.of()))));
            }
        }
        if (found.isEmpty()) {
            throw new IllegalArgumentException(dir + " holds no submissions (subfolders or .zip files)");
        }
        return found;
    }

    /** The names of its students, "; " between them (a group submission has several). */
    public String names() {
        return submitters.stream().map(Submitter::name).collect(Collectors.joining("; "));
    }

    public String emails() {
        return submitters.stream().map(Submitter::email).collect(Collectors.joining("; "));
    }

    /** Their student IDs (Gradescope's {@code :sid:}), "; " between them. */
    public String sids() {
        return submitters.stream().map(Submitter::sid).collect(Collectors.joining("; "));
    }

    /** When it last changed: a zip's time, or the newest file's in a folder (a re-upload touches them). */
    public FileTime lastModified() throws IOException {
        try (Stream<Path> walk = Files.walk(path)) {
            FileTime newest = FileTime.fromMillis(0);
            for (Path p : walk.collect(Collectors.toList())) {
                FileTime t = Files.getLastModifiedTime(p);
                newest = t.compareTo(newest) > 0 ? t : newest;
            }
            return newest;
        }
    }

    private static boolean sameFile(Path a, Path b) throws IOException {
        return b != null && Files.exists(b) && Files.isSameFile(a, b);
    }
}
