package ray.grading;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/**
 * Compiles a project tree's main and test sources (src/main/java, src/test/java and, in the
 * instructor's tree, src/instructor/java and src/instructorTest/java) into one folder, in this JVM, and copies their
 * resources beside the classes, with the instructor's assignment file where the build puts it. The compiler's messages are kept for the student.
 */
public final class ProjectCompiler {
    private static final List<String> SOURCE_FOLDERS = List.of("src/main/java", "src/instructor/java", "src/test/java",
            "src/instructorTest/java");
    private static final List<String> RESOURCE_FOLDERS = List.of("src/main/resources", "src/instructor/resources",
            "src/test/resources", "src/instructorTest/resources");

    private ProjectCompiler() {
    }

    /**
     * @param classpath the libraries the sources need (JUnit, picocli, ...), as a path-separated list
     */
    public static CompileResult compile(Path project, Path classesDir, String classpath) throws IOException {
        List<Path> sources = new ArrayList<>();
        for (String folder : SOURCE_FOLDERS) {
            Path dir = project.resolve(folder);
            if (Files.isDirectory(dir)) {
                try (Stream<Path> walk = Files.walk(dir)) {
                    sources.addAll(walk.filter(p -> p.toString().endsWith(".java")).sorted().collect(Collectors.toList()));
                }
            }
        }
        CompileResult result = compile(project, sources, classesDir, classpath);
        for (String folder : RESOURCE_FOLDERS) {
            Path dir = project.resolve(folder);
            if (Files.isDirectory(dir)) {
                ProjectTree.copyRecursively(dir, classesDir);
            }
        }
        // The instructor's assignment file goes where the build puts it (gradle/instructor.gradle):
        // the tests and the framework read the assignment from the classpath.
        Path assignment = project.resolve(ray.assignment.Assignment.PROJECT_FILE);
        if (Files.isRegularFile(assignment)) {
            Path onClasspath = classesDir.resolve(ray.assignment.Assignment.RESOURCE);
            Files.createDirectories(onClasspath.getParent());
            Files.copy(assignment, onClasspath, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        return result;
    }

    /**
     * Compiles only {@code sources} (files under {@code project}) into {@code classesDir} against
     * {@code classpath}: a task's few student files against the compiled instructor tree, which is
     * what grading a task needs (the rest of the tree is compiled once per submission, not per task).
     */
    public static CompileResult compile(Path project, List<Path> sources, Path classesDir, String classpath) throws IOException {
        ProjectTree.deleteRecursively(classesDir);
        return compileInto(project, sources, classesDir, classpath);
    }

    /** Compiles {@code sources} into {@code classesDir}, keeping what it holds already. */
    public static CompileResult compileInto(Path project, List<Path> sources, Path classesDir, String classpath) throws IOException {
        JavaCompiler compiler = ToolProvider.getSystemJavaCompiler();
        if (compiler == null) {
            throw new IllegalStateException("no Java compiler in this runtime: grading needs a JDK, not a JRE");
        }
        Files.createDirectories(classesDir);
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        StringWriter output = new StringWriter();
        boolean ok;
        try (StandardJavaFileManager files = compiler.getStandardFileManager(diagnostics, null, StandardCharsets.UTF_8)) {
            // No annotation processing: nothing on the class path runs while a submission compiles.
            List<String> options = List.of("--release", "17", "-encoding", "UTF-8", "-nowarn", "-proc:none", "-Xmaxerrs", "20",
                    "-d", classesDir.toString(), "-cp", classpath);
            ok = compiler.getTask(output, files, diagnostics, options, null,
                    files.getJavaFileObjectsFromPaths(sources)).call();
        }
        return new CompileResult(ok, describe(project, diagnostics) + output);
    }

    private static String describe(Path project, DiagnosticCollector<JavaFileObject> diagnostics) {
        StringBuilder text = new StringBuilder();
        diagnostics.getDiagnostics().stream()
                .filter(d -> d.getKind() == javax.tools.Diagnostic.Kind.ERROR)
                .forEach(d -> {
                    String source = d.getSource() == null ? "" : project.toAbsolutePath().relativize(
                            Path.of(d.getSource().toUri()).toAbsolutePath()).toString().replace('\\', '/');
                    text.append(source).append(':').append(d.getLineNumber()).append(": error: ")
                            .append(d.getMessage(null)).append('\n');
                });
        return text.toString();
    }
}
