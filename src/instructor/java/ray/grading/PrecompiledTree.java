package ray.grading;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * The grading tree's classes compiled once, when the autograder is packed, rather than at every
 * grading: {@code compiled/} beside the tree's sources holds what the grader would compile (the tree's
 * {@code classes/}, {@code handout/} and {@code standins/}, see {@link GradingClasses}) and the
 * fingerprint of the sources they came from. A grader uses them only while the sources are still
 * those; otherwise (an edited package, or a project that was never packed) it compiles as before.
 */
public final class PrecompiledTree {
    /** The folder beside the sources. */
    public static final String FOLDER = "compiled";
    private static final List<String> PARTS = List.of("classes", "handout", "standins");
    private static final String SOURCES = "sources.sha256";

    private PrecompiledTree() {
    }

    /**
     * Compiles the tree at {@code tree} (its src/ and the rest as the grader copies them) as a grading
     * would, into {@code tree}/compiled, with {@code classpath} the libraries.
     */
    public static void compile(Path tree, String classpath) throws IOException {
        CompileResult compiled = ProjectCompiler.compile(tree, tree.resolve("classes"), classpath);
        if (!compiled.ok()) {
            throw new IllegalStateException("the instructor's tree does not compile:\n" + compiled.messages());
        }
        GradingClasses.prepare(tree, classpath);
        Path out = tree.resolve(FOLDER);
        ProjectTree.deleteRecursively(out);
        Files.createDirectories(out);
        for (String part : PARTS) {
            Files.move(tree.resolve(part), out.resolve(part));
        }
        Files.writeString(out.resolve(SOURCES), sources(tree), StandardCharsets.UTF_8);
    }

    /**
     * Gives {@code tree} (a copy of {@code project}'s sources) the classes {@code project} was packed
     * with, when they were compiled from these very sources; false when there are none to use.
     */
    static boolean useFor(Path project, Path tree) throws IOException {
        Path compiled = project.resolve(FOLDER);
        if (!Files.isRegularFile(compiled.resolve(SOURCES))
                || !Files.readString(compiled.resolve(SOURCES), StandardCharsets.UTF_8).equals(sources(tree))) {
            return false;
        }
        for (String part : PARTS) {
            ProjectTree.deleteRecursively(tree.resolve(part));
            ProjectTree.copyRecursively(compiled.resolve(part), tree.resolve(part));
        }
        return true;
    }

    /** The fingerprint of the tree's sources (everything under src/). */
    /** The fingerprint of the tree's sources and its assignment file (which the compiled classes carry). */
    private static String sources(Path tree) throws IOException {
        Path assignment = tree.resolve(ray.assignment.Assignment.PROJECT_FILE);
        return CompiledTree.fingerprint(tree, tree.resolve("src"))
                + (Files.isRegularFile(assignment) ? "+" + CompiledTree.fingerprint(tree, assignment) : "");
    }
}
