package ray.testing;

import com.google.gson.GsonBuilder;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.Writer;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import junit.framework.TestCase;
import org.junit.Test;
import org.junit.runner.Description;
import org.junit.runner.JUnitCore;
import org.junit.runner.Request;
import org.junit.runner.RunWith;
import org.junit.runner.Runner;
import org.junit.runner.manipulation.Filter;
import org.junit.runner.manipulation.NoTestsRemainException;
import org.junit.runner.notification.Failure;
import org.junit.runner.notification.RunListener;

/**
 * Runs test classes with JUnit 4 directly, outside a build tool's test worker, and writes what
 * happened as JSON for the build to report.
 *
 * <p>Why it exists: Debian's Gradle 4.4 runs tests in a worker that sets a security manager, and
 * Java 24 and later refuse that call outright (JEP 486), so on those Javas the worker dies and
 * {@code gradle test} fails whatever the tests say. The build ({@code gradle/legacy-test-worker.gradle})
 * then starts this class instead, with the same classpath, and prints the same summary from its
 * results. Newer Gradle versions never need it.
 *
 * <pre>
 * java ray.testing.StandaloneTestRun --results FILE --output FILE [--filter PATTERN]... CLASS...
 * </pre>
 *
 * <p>{@code --filter} takes {@code gradle test --tests} patterns: a class name, fully qualified or
 * simple, optionally followed by {@code .method}, with {@code *} as a wildcard. A class with no
 * tests (a helper, an abstract base) is skipped, as Gradle's scan skips it. What the tests print
 * goes to the output file, so the console keeps only the summary, as under Gradle.
 */
public final class StandaloneTestRun {
    private StandaloneTestRun() {
    }

    /** One failed test: where, the exception's class and its message. */
    record TestFailure(String className, String name, String exceptionClass, String message) {
    }

    /** The results file's content. */
    record Results(int passed, int failed, int skipped, List<TestFailure> failures) {
    }

    public static void main(String[] args) throws IOException, ClassNotFoundException {
        Path results = null;
        Path output = null;
        List<String> filters = new ArrayList<>();
        List<String> classNames = new ArrayList<>();
        for (int n = 0; n < args.length; n++) {
            switch (args[n]) {
                case "--results" -> results = Path.of(args[++n]);
                case "--output" -> output = Path.of(args[++n]);
                case "--filter" -> filters.add(args[++n]);
                default -> classNames.add(args[n]);
            }
        }
        if (results == null || output == null) {
            throw new IllegalArgumentException("usage: StandaloneTestRun --results FILE --output FILE [--filter PATTERN]... CLASS...");
        }
        Files.createDirectories(output.toAbsolutePath().getParent());
        Results outcome;
        PrintStream console = System.out;
        PrintStream errors = System.err;
        try (PrintStream captured = new PrintStream(new FileOutputStream(output.toFile()), true, StandardCharsets.UTF_8)) {
            System.setOut(captured);
            System.setErr(captured);
            outcome = run(testClasses(classNames), filters);
        } finally {
            System.setOut(console);
            System.setErr(errors);
        }
        Files.createDirectories(results.toAbsolutePath().getParent());
        try (Writer writer = Files.newBufferedWriter(results, StandardCharsets.UTF_8)) {
            new GsonBuilder().setPrettyPrinting().create().toJson(outcome, writer);
        }
    }

    /** The named classes that hold tests, loaded without initializing them. */
    static List<Class<?>> testClasses(List<String> names) throws ClassNotFoundException {
        List<Class<?>> classes = new ArrayList<>();
        ClassLoader loader = StandaloneTestRun.class.getClassLoader();
        for (String name : names) {
            Class<?> type = Class.forName(name, false, loader);
            if (holdsTests(type)) {
                classes.add(type);
            }
        }
        return classes;
    }

    /** Whether JUnit 4 can run {@code type}: a concrete public class with @Test methods, a runner, or JUnit 3 tests. */
    static boolean holdsTests(Class<?> type) {
        int modifiers = type.getModifiers();
        if (type.isInterface() || Modifier.isAbstract(modifiers) || !Modifier.isPublic(modifiers) || type.isMemberClass()) {
            return false;
        }
        if (type.isAnnotationPresent(RunWith.class) || TestCase.class.isAssignableFrom(type)) {
            return true;
        }
        for (Method method : type.getMethods()) {
            if (method.isAnnotationPresent(Test.class)) {
                return true;
            }
        }
        return false;
    }

    /** Runs {@code classes} (only the tests that {@code filters} select, if any) and counts as Gradle counts. */
    static Results run(List<Class<?>> classes, List<String> filters) {
        Map<Description, TestFailure> failures = new LinkedHashMap<>();
        int[] finished = {0};
        int[] assumptionsFailed = {0};
        int[] ignored = {0};
        JUnitCore core = new JUnitCore();
        core.addListener(new RunListener() {
            @Override
            public void testFinished(Description description) {
                finished[0]++;
            }

            @Override
            public void testFailure(Failure failure) {
                failures.put(failure.getDescription(), failureOf(failure));
            }

            @Override
            public void testAssumptionFailure(Failure failure) {
                assumptionsFailed[0]++;
            }

            @Override
            public void testIgnored(Description description) {
                ignored[0]++;
            }
        });
        // Class by class, so that a class none of whose tests the filter selects is left out quietly,
        // as Gradle leaves it out (JUnit would report it as a failure).
        Filter filter = filters.isEmpty() ? Filter.ALL : new PatternFilter(filters);
        for (Class<?> type : classes) {
            Runner runner = Request.aClass(type).getRunner();
            try {
                filter.apply(runner);
            } catch (NoTestsRemainException notSelected) {
                continue;
            }
            core.run(runner);
        }
        // A finished test passed unless it failed or its assumption did not hold (skipped); an ignored
        // test never starts. A failure outside any test (a class's @BeforeClass) counts as one failed
        // test, as Gradle counts it.
        long failedTests = failures.keySet().stream().filter(d -> d.getMethodName() != null).count();
        int passed = (int) Math.max(0, finished[0] - failedTests - assumptionsFailed[0]);
        return new Results(passed, failures.size(), assumptionsFailed[0] + ignored[0], new ArrayList<>(failures.values()));
    }

    private static TestFailure failureOf(Failure failure) {
        Description description = failure.getDescription();
        Throwable exception = failure.getException();
        String message = exception.getMessage() != null ? exception.getMessage() : exception.toString();
        return new TestFailure(description.getClassName(),
                description.getMethodName() != null ? description.getMethodName() : "classMethod",
                exception.getClass().getName(), message);
    }

    /** {@code gradle test --tests} patterns: a class (qualified or simple) and optionally a method, {@code *} any text. */
    static final class PatternFilter extends Filter {
        private final List<Pattern> patterns;
        private final String text;

        PatternFilter(List<String> patterns) {
            this.patterns = patterns.stream()
                    .map(p -> Pattern.compile(p.chars().mapToObj(c -> c == '*' ? ".*" : Pattern.quote(String.valueOf((char) c)))
                            .collect(Collectors.joining())))
                    .collect(Collectors.toList());
            this.text = String.join(", ", patterns);
        }

        @Override
        public boolean shouldRun(Description description) {
            if (description.isSuite()) {
                return description.getChildren().stream().anyMatch(this::shouldRun);
            }
            String className = description.getClassName();
            String simpleName = className.substring(className.lastIndexOf('.') + 1);
            String method = description.getMethodName();
            for (Pattern pattern : patterns) {
                for (String name : List.of(className, simpleName)) {
                    if (pattern.matcher(name).matches() || (method != null && pattern.matcher(name + "." + method).matches())) {
                        return true;
                    }
                }
            }
            return false;
        }

        @Override
        public String describe() {
            return "tests matching " + text;
        }
    }
}
