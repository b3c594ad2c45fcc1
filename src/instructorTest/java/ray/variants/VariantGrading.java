package ray.variants;

import java.io.File;
import java.io.IOException;
import java.lang.annotation.Annotation;
import java.lang.reflect.Modifier;
import java.net.URL;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.runner.Description;
import org.junit.runner.JUnitCore;
import org.junit.runner.Request;
import org.junit.runner.manipulation.Filter;
import org.junit.runner.notification.Failure;
import org.junit.runner.notification.RunListener;
import ray.grading.PointsAnnotation;

/**
 * Grades a {@link Variant} in this JVM, as the grader would its task: its files are compiled
 * against the build's classes, every {@code ray.*} class is loaded afresh with them in place
 * ({@link VariantLoader}), and the graded tests chosen by task run through JUnit. Each test's
 * points come from its {@code @Points}, read as the grader reads them ({@link PointsAnnotation}).
 */
final class VariantGrading {
    /** What one graded test did. */
    static final class Outcome {
        final String test;
        final int task;
        final double points;
        final boolean bonus;
        final String failure;

        Outcome(String test, int task, double points, boolean bonus, String failure) {
            this.test = test;
            this.task = task;
            this.points = points;
            this.bonus = bonus;
            this.failure = failure;
        }

        boolean passed() {
            return failure == null;
        }

        @Override
        public String toString() {
            return test + (bonus ? " (bonus)" : "") + ": " + (passed() ? "passed" : failure.lines().findFirst().orElse(""));
        }
    }

    private VariantGrading() {
    }

    /** Which graded tests to run: by their task and their class. */
    interface Selection {
        boolean includes(int task, String testClass);
    }

    /** The graded tests that {@code selection} includes, run with {@code variant}'s files in place. */
    static List<Outcome> run(Variant variant, Selection selection, Path work) throws Exception {
        Path classes = compile(variant, work);
        List<URL> urls = new ArrayList<>();
        urls.add(classes.toUri().toURL());
        for (String entry : classPath()) {
            urls.add(Path.of(entry).toUri().toURL());
        }
        List<Outcome> outcomes = new ArrayList<>();
        try (VariantLoader loader = new VariantLoader(urls.toArray(new URL[0]), VariantGrading.class.getClassLoader())) {
            JUnitCore core = new JUnitCore();
            core.addListener(new Recorder(outcomes));
            for (String name : testClassNames()) {
                Class<?> type = Class.forName(name, false, loader);
                if (Modifier.isAbstract(type.getModifiers())) {
                    continue;
                }
                Filter filter = new Filter() {
                    @Override
                    public boolean shouldRun(Description d) {
                        if (!d.isTest()) {
                            return d.getChildren().stream().anyMatch(this::shouldRun);
                        }
                        Annotation points = PointsAnnotation.of(d);
                        return points != null && selection.includes(taskOf(d.getClassName()), d.getClassName());
                    }

                    @Override
                    public String describe() {
                        return "graded tests";
                    }
                };
                if (filter.shouldRun(Request.aClass(type).getRunner().getDescription())) {
                    core.run(Request.aClass(type).filterWith(filter));
                }
            }
        }
        return outcomes;
    }

    static Path compile(Variant variant, Path work) throws IOException {
        Path out = work.resolve(variant.name);
        Files.createDirectories(out);
        List<String> sources;
        try (Stream<Path> files = Files.walk(variant.folder())) {
            sources = files.filter(p -> p.toString().endsWith(".java")).map(Path::toString).collect(Collectors.toList());
        }
        if (sources.isEmpty()) {
            throw new IllegalStateException(variant.folder() + " holds no .java file");
        }
        String errors = StubBuild.javac(sources, out);
        if (errors != null) {
            throw new IllegalStateException("variant " + variant + " does not compile:\n" + errors);
        }
        return out;
    }

    static List<String> classPath() {
        return List.of(System.getProperty("java.class.path").split(File.pathSeparator));
    }

    /** Every test class in the build's class folders (the graded ones are filtered by their @Points). */
    private static List<String> testClassNames() throws IOException {
        List<String> names = new ArrayList<>();
        for (String entry : classPath()) {
            Path folder = Path.of(entry);
            if (!Files.isDirectory(folder.resolve("ray"))) {
                continue;
            }
            try (Stream<Path> files = Files.walk(folder.resolve("ray"))) {
                files.map(p -> folder.relativize(p).toString().replace(File.separatorChar, '/'))
                        .filter(p -> p.endsWith("Test.class") && !p.contains("$"))
                        .map(p -> p.substring(0, p.length() - ".class".length()).replace('/', '.'))
                        .sorted()
                        .forEach(names::add);
            }
        }
        return names;
    }

    /** The number of test class {@code className}'s task in this assignment (the table of tasks gives a class its task). */
    static int taskOf(String className) {
        return ray.assignment.Assignment.current().table().ofTestClass(className)
                .map(t -> ray.assignment.Assignment.current().number(t.id())).orElse(0);
    }

    /** Whether the test is extra credit: its own @Points says so, or its task is. */
    static boolean bonusOf(String className, Annotation points) {
        ray.assignment.Assignment a = ray.assignment.Assignment.current();
        return (Boolean) PointsAnnotation.element(points, "bonus")
                || a.table().ofTestClass(className).map(t -> a.isExtraCredit(t.id())).orElse(false);
    }

    /** Turns JUnit's events into outcomes. */
    private static final class Recorder extends RunListener {
        private final List<Outcome> outcomes;
        private String failure;

        Recorder(List<Outcome> outcomes) {
            this.outcomes = outcomes;
        }

        @Override
        public void testStarted(Description d) {
            failure = null;
        }

        @Override
        public void testFailure(Failure f) {
            failure = String.valueOf(f.getException());
        }

        @Override
        public void testAssumptionFailure(Failure f) {
            failure = "skipped: " + f.getMessage();
        }

        @Override
        public void testFinished(Description d) {
            Annotation points = PointsAnnotation.of(d);
            outcomes.add(new Outcome(d.getClassName() + "#" + d.getMethodName(), taskOf(d.getClassName()),
                    ((Number) PointsAnnotation.element(points, "value")).doubleValue(), bonusOf(d.getClassName(), points), failure));
        }
    }
}
