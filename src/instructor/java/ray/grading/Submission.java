package ray.grading;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;

/**
 * What a student handed in: a folder or a zip, laid out like the handout (possibly inside one
 * top folder), or just the edited files side by side (as Gradescope uploads often are). Only the
 * student-fillable files are taken; everything else is listed as ignored, except the
 * {@link SubmissionManifest} that the students' {@code gradle submission} packs with them.
 */
public final class Submission {
    /** Relative path in the project → the submitted file. */
    public final Map<String, Path> files;
    /** Student files the submission lacks. */
    public final List<String> missing;
    /** Submitted files that are not student files (tests, framework, build files, ...), never used. */
    public final List<String> ignored;
    /** The checksums {@code gradle submission} recorded ({@link SubmissionManifest}), or null when there are none. */
    public final Path manifest;

    private Submission(Map<String, Path> files, List<String> missing, List<String> ignored, Path manifest) {
        this.files = files;
        this.missing = missing;
        this.ignored = ignored;
        this.manifest = manifest;
    }

    /**
     * @param submission  a folder or a .zip file
     * @param wanted      the student files' paths relative to the project, e.g. src/main/java/ray/surface/Sphere.java
     * @param unpackInto  where a zip is unpacked
     */
    public static Submission locate(Path submission, Collection<String> wanted, Path unpackInto) throws IOException {
        Path root = submission;
        if (Files.isRegularFile(submission) && submission.toString().toLowerCase().endsWith(".zip")) {
            root = unzip(submission, unpackInto);
        } else if (!Files.isDirectory(submission)) {
            throw new IOException(submission + " is neither a folder nor a .zip file");
        }
        List<String> all;
        Path base = root;
        try (Stream<Path> walk = Files.walk(root)) {
            all = walk.filter(Files::isRegularFile).map(p -> base.relativize(p).toString().replace('\\', '/'))
                    .filter(p -> !p.startsWith("__MACOSX/") && !p.endsWith(".DS_Store"))
                    .sorted().collect(Collectors.toList());
        }
        Map<String, Path> found = new LinkedHashMap<>();
        List<String> missing = new ArrayList<>();
        TreeSet<String> used = new TreeSet<>();
        for (String path : wanted) {
            String match = bestMatch(path, all);
            if (match == null) {
                missing.add(path);
            } else {
                found.put(path, root.resolve(match));
                used.add(match);
            }
        }
        // The manifest beside the files (at the top, or in the top folder): the shortest path wins, as for a student file.
        String manifest = all.stream().filter(p -> p.equals(SubmissionManifest.NAME) || p.endsWith("/" + SubmissionManifest.NAME))
                .min(Comparator.comparingInt(String::length)).orElse(null);
        if (manifest != null) {
            used.add(manifest);
        }
        List<String> ignored = all.stream().filter(p -> !used.contains(p)).collect(Collectors.toList());
        return new Submission(found, missing, ignored, manifest == null ? null : root.resolve(manifest));
    }

    /**
     * The submitted file for {@code path}: one at the same relative path (possibly under a top
     * folder), else one with the same file name anywhere; the shortest such path wins.
     */
    private static String bestMatch(String path, List<String> all) {
        String name = path.substring(path.lastIndexOf('/') + 1);
        return all.stream().filter(p -> p.equals(path) || p.endsWith("/" + path)).min(Comparator.comparingInt(String::length))
                .orElseGet(() -> all.stream().filter(p -> p.equals(name) || p.endsWith("/" + name))
                        .min(Comparator.comparingInt(String::length)).orElse(null));
    }

    /** Unpacks a zip, refusing entries that would land outside the target folder ("zip slip"). */
    private static Path unzip(Path zip, Path target) throws IOException {
        ProjectTree.deleteRecursively(target);
        Files.createDirectories(target);
        Path normalTarget = target.toAbsolutePath().normalize();
        try (InputStream in = Files.newInputStream(zip); ZipInputStream entries = new ZipInputStream(in)) {
            for (ZipEntry entry = entries.getNextEntry(); entry != null; entry = entries.getNextEntry()) {
                Path destination = normalTarget.resolve(entry.getName()).normalize();
                if (!destination.startsWith(normalTarget)) {
                    throw new IOException(zip + ": entry " + entry.getName() + " points outside the submission");
                }
                if (entry.isDirectory()) {
                    Files.createDirectories(destination);
                } else {
                    Files.createDirectories(destination.getParent());
                    Files.copy(entries, destination, StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
        return target;
    }
}
