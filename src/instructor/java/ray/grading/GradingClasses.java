package ray.grading;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import ray.grading.worker.WorkerMain;

/**
 * The compiled instructor tree's classes, laid out for the two processes of a grading:
 * <ul>
 * <li>{@code handout/}, the worker's: the framework as the handout ships it (the tree's main classes
 * with every student class replaced by the handout's stub) and the worker's own code (the wire format
 * and {@link WorkerMain}), and nothing else: no test, no hidden test, no solution. A student's files
 * compile against it, and run on it with their classes first;</li>
 * <li>{@code standins/}, the judge's: the stand-in of every student class ({@link StandInSources}),
 * put first on the judge's class path: while task N is graded, the tests call the worker for task
 * N's classes and run the solution for every other task's.</li>
 * </ul>
 */
final class GradingClasses {
    /** The packages of grading code the worker runs besides the framework. */
    private static final List<String> WORKER_PACKAGES = List.of("ray/grading/wire/", "ray/grading/worker/");

    private GradingClasses() {
    }

    static Path handout(Path tree) {
        return tree.resolve("handout");
    }

    static Path standIns(Path tree) {
        return tree.resolve("standins");
    }

    /**
     * Writes {@code handout/} and {@code standins/} of {@code tree}, whose {@code classes/} holds the
     * compiled instructor tree; {@code classpath} is the tree's libraries.
     */
    static void prepare(Path tree, String classpath) throws IOException {
        Path classes = tree.resolve("classes");
        Map<String, Integer> studentFiles = StudentFiles.in(tree);
        Path handout = handout(tree);
        ProjectTree.deleteRecursively(handout);
        Files.createDirectories(handout);
        copyMainClasses(tree, classes, handout, studentFiles.keySet());
        // The framework reads the table of tasks and the assignment from its class path (a surface's kind names its task).
        Path assignment = classes.resolve("ray/assignment");
        if (Files.isDirectory(assignment)) {
            ProjectTree.copyRecursively(assignment, handout.resolve("ray/assignment"));
        }
        List<Path> stubs = new ArrayList<>();
        List<Path> standIns = new ArrayList<>();
        for (Map.Entry<String, Integer> file : studentFiles.entrySet()) {
            String solution = Files.readString(tree.resolve(file.getKey()), StandardCharsets.UTF_8);
            Path stubFile = tree.resolve("stubs").resolve(file.getKey());
            Files.createDirectories(stubFile.getParent());
            Files.writeString(stubFile, SolutionMarkers.studentVersion(solution, file.getKey()), StandardCharsets.UTF_8);
            stubs.add(stubFile);
            Path standIn = tree.resolve("standins-src").resolve(file.getKey());
            Files.createDirectories(standIn.getParent());
            Files.writeString(standIn, StandInSources.of(solution, file.getKey(), file.getValue()), StandardCharsets.UTF_8);
            standIns.add(standIn);
        }
        if (!stubs.isEmpty()) {
            CompileResult stubsCompiled = ProjectCompiler.compileInto(tree, stubs, handout, handout.toString());
            if (!stubsCompiled.ok()) {
                throw new IllegalStateException("the handout's stubs do not compile against the framework:\n" + stubsCompiled.messages());
            }
        }
        copyWorkerClasses(handout);
        ProjectTree.deleteRecursively(standIns(tree));
        Files.createDirectories(standIns(tree));
        if (!standIns.isEmpty()) {
            CompileResult compiled = ProjectCompiler.compile(tree, standIns, standIns(tree), classes + File.pathSeparator + classpath);
            if (!compiled.ok()) {
                throw new IllegalStateException("the stand-ins do not compile:\n" + compiled.messages());
            }
        }
    }

    /** The tree's classes compiled from src/main/java, but the student files': the framework. */
    private static void copyMainClasses(Path tree, Path classes, Path handout, Iterable<String> studentFiles) throws IOException {
        Path main = tree.resolve("src/main/java");
        List<String> student = new ArrayList<>();
        studentFiles.forEach(f -> student.add(f.substring("src/main/java/".length(), f.length() - ".java".length())));
        List<Path> files;
        try (Stream<Path> walk = Files.walk(classes)) {
            files = walk.filter(Files::isRegularFile).collect(Collectors.toList());
        }
        for (Path file : files) {
            String name = classes.relativize(file).toString().replace(File.separatorChar, '/');
            if (!name.endsWith(".class")) {
                continue;
            }
            String topLevel = name.substring(0, name.length() - ".class".length());
            int nested = topLevel.indexOf('$');
            topLevel = nested < 0 ? topLevel : topLevel.substring(0, nested);
            if (Files.isRegularFile(main.resolve(topLevel + ".java")) && !student.contains(topLevel)) {
                Path target = handout.resolve(name);
                Files.createDirectories(target.getParent());
                Files.copy(file, target);
            }
        }
    }

    /** The worker's own classes, from wherever the grader's classes are (a folder, or the grader's jar). */
    private static void copyWorkerClasses(Path handout) throws IOException {
        Path source;
        try {
            source = Path.of(WorkerMain.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException e) {
            throw new IOException(e);
        }
        if (Files.isDirectory(source)) {
            for (String pkg : WORKER_PACKAGES) {
                Path from = source.resolve(pkg);
                try (Stream<Path> files = Files.list(from)) {
                    for (Path f : files.filter(p -> p.toString().endsWith(".class")).collect(Collectors.toList())) {
                        Path target = handout.resolve(pkg).resolve(f.getFileName().toString());
                        Files.createDirectories(target.getParent());
                        Files.copy(f, target);
                    }
                }
            }
            return;
        }
        try (JarFile jar = new JarFile(source.toFile())) {
            for (JarEntry e : java.util.Collections.list(jar.entries())) {
                String name = e.getName();
                for (String pkg : WORKER_PACKAGES) {
                    if (name.startsWith(pkg) && name.endsWith(".class") && name.indexOf('/', pkg.length()) < 0) {
                        Path target = handout.resolve(name);
                        Files.createDirectories(target.getParent());
                        try (InputStream in = jar.getInputStream(e)) {
                            Files.write(target, in.readAllBytes());
                        }
                    }
                }
            }
        }
    }
}
