package ray.tools;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * The files of a project folder that a package should hold: those git tracks, when the project is a
 * git checkout, so an instructor's scratch files, editor backups and half-written variants never
 * reach a platform; every file under the folder otherwise (a project unpacked from an archive). A
 * tracked file is read as it is in the working tree, edits included.
 */
final class TrackedFiles {
    private static final int GIT_LIMIT_SECONDS = 60;

    private TrackedFiles() {
    }

    /** The files under {@code project/part}, sorted, so two builds of one project write the same package. */
    static List<Path> under(Path project, String part) throws IOException {
        List<Path> tracked = gitLsFiles(project, part);
        if (tracked != null) {
            return tracked;
        }
        Path base = project.toAbsolutePath().normalize();
        try (Stream<Path> walk = Files.walk(base.resolve(part).normalize())) {
            return walk.filter(Files::isRegularFile).map(file -> project.resolve(base.relativize(file).toString()))
                    .sorted().collect(Collectors.toList());
        }
    }

    /** git's list of tracked files under the part that exist in the working tree, or null when git cannot say. */
    private static List<Path> gitLsFiles(Path project, String part) throws IOException {
        if (!Files.exists(project.resolve(".git"))) {
            return null;
        }
        Process git;
        try {
            git = new ProcessBuilder("git", "-C", project.toString(), "ls-files", "-z", "--", part)
                    .redirectError(ProcessBuilder.Redirect.DISCARD).start();
        } catch (IOException noGit) {
            return null;
        }
        byte[] listing;
        try (InputStream out = git.getInputStream()) {
            ByteArrayOutputStream bytes = new ByteArrayOutputStream();
            out.transferTo(bytes);
            listing = bytes.toByteArray();
            if (!git.waitFor(GIT_LIMIT_SECONDS, TimeUnit.SECONDS) || git.exitValue() != 0) {
                git.destroyForcibly();
                return null;
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            git.destroyForcibly();
            return null;
        }
        List<Path> files = new ArrayList<>();
        for (String name : new String(listing, StandardCharsets.UTF_8).split("\0")) {
            Path file = project.resolve(name);
            if (!name.isEmpty() && Files.isRegularFile(file)) {
                files.add(file);
            }
        }
        files.sort(null);
        return files;
    }
}
