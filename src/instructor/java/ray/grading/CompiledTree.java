package ray.grading;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.security.DigestInputStream;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * The instructor's tree copied and compiled once for a whole {@code gradeAll} run, instead of once
 * per submission (compiling it is most of a correct submission's grading time otherwise). Each
 * grading gets a copy of it ({@link #copyTo}: the sources, scenes and classes, no compile) to run
 * its tests in, exactly as it would have compiled its own, so nothing a submission does there
 * reaches another one; the tree itself is only ever read.
 *
 * <p>It is a snapshot: edits to the project while gradeAll runs change no grading. And it is
 * checked: {@link #unchanged()} compares every file with its fingerprint from when it was compiled,
 * so that gradeAll notices when student code found the tree and wrote to it (it can, while the test
 * JVM runs as the grader's user), stops using it and grades again on a fresh one. Beside it, what
 * every grading would otherwise work out again for itself: each task's list of graded tests, and
 * what the known mistakes do ({@link MistakeEvidence}).
 */
public final class CompiledTree {
    private final Path root;
    private final String fingerprint;
    private final Map<Integer, List<TestOutcome>> listed = new HashMap<>();
    private final MistakeEvidence mistakeEvidence;
    private volatile boolean spoiled;

    private CompiledTree(Path root, String fingerprint, String classpath) {
        this.root = root;
        this.fingerprint = fingerprint;
        this.mistakeEvidence = new MistakeEvidence(root, classpath);
    }

    /**
     * Copies {@code project}'s sources and scenes to {@code at} (a new folder) and compiles them there.
     *
     * @throws IllegalStateException with the compiler's messages when the tree does not compile
     */
    public static CompiledTree build(Path project, Path at, String classpath) throws IOException {
        ProjectTree.copy(project, at, Map.of());
        CompileResult compiled = ProjectCompiler.compile(at, at.resolve("classes"), classpath);
        if (!compiled.ok()) {
            ProjectTree.deleteRecursively(at);
            throw new IllegalStateException("the instructor's tree does not compile:\n" + compiled.messages());
        }
        GradingClasses.prepare(at, classpath);
        return new CompiledTree(at, fingerprint(at), classpath);
    }

    public Path root() {
        return root;
    }

    /** A grading's own copy of the compiled tree at {@code target}, which must not exist yet. */
    void copyTo(Path target) throws IOException {
        ProjectTree.copyRecursively(root, target);
    }

    /**
     * Whether every file is as it was compiled (and no file came or went). Once it is not, it never
     * is again: the tree is not to be used any more.
     */
    public boolean unchanged() throws IOException {
        if (!spoiled && !fingerprint.equals(fingerprint(root))) {
            spoiled = true;
        }
        return !spoiled;
    }

    /** The graded tests of {@code task} (null: all), listed once for every grading that needs them. */
    List<TestOutcome> tests(Integer task, Lister lister) throws IOException, InterruptedException {
        synchronized (listed) {
            List<TestOutcome> tests = listed.get(task);
            if (tests == null) {
                tests = List.copyOf(lister.list());
                listed.put(task, tests);
            }
            return tests;
        }
    }

    /** Lists graded tests, as {@link TestProcess#list} does. */
    interface Lister {
        List<TestOutcome> list() throws IOException, InterruptedException;
    }

    /** What the known mistakes do (renders, failed tests), measured in this tree (its variants, scenes and classes) once for every grading. */
    MistakeEvidence mistakeEvidence() {
        return mistakeEvidence;
    }

    /**
     * SHA-256 of every file under {@code tree}: its path and its bytes, in path order. A few MB of
     * sources, scenes and classes: tens of milliseconds.
     */
    static String fingerprint(Path tree) throws IOException {
        return fingerprint(tree, tree);
    }

    /** SHA-256 of every file under {@code part} (a folder of {@code tree}), named from {@code tree}. */
    static String fingerprint(Path tree, Path part) throws IOException {
        MessageDigest digest;
        try {
            digest = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
        List<Path> files;
        try (Stream<Path> walk = Files.walk(part)) {
            files = walk.filter(p -> !p.equals(tree)).sorted().collect(Collectors.toList());
        }
        byte[] buffer = new byte[1 << 16];
        for (Path p : files) {
            String name = tree.relativize(p).toString().replace('\\', '/');
            // Each entry: its name, what it is (and a file's size), then a file's bytes.
            String kind = Files.isSymbolicLink(p) ? "link to " + Files.readSymbolicLink(p)
                    : Files.isDirectory(p) ? "folder" : "file of " + Files.size(p) + " bytes";
            digest.update((name + '\0' + kind + '\0').getBytes(StandardCharsets.UTF_8));
            if (Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
                try (InputStream in = new DigestInputStream(Files.newInputStream(p), digest)) {
                    while (in.read(buffer) >= 0) {
                        // The digest reads along.
                    }
                }
            }
        }
        return HexFormat.of().formatHex(digest.digest());
    }
}
