package ray.grading;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Collectors;
import javax.imageio.ImageIO;
import ray.grading.VariantFolders.Variant;
import ray.image.ImageDiff;

/**
 * Names a known mistake only where the student's results are that mistake's, measured. The
 * instructor's tree keeps known-wrong versions of the student files (src/instructorTest/variants,
 * each class saying "Known wrong: what it does"); when a task's tests fail, its known mistakes are
 * run in the student's place ({@link MistakeEvidence}) and a mistake is named
 * <ul>
 * <li>in a failed render test, when its render of the scene matches the student's by the render
 *     tests' own comparison <em>and</em> it fails the same unit tests of the task as the student's
 *     code (a render that merely looks like a mistake's is not enough: an inward normal and a sphere
 *     that ignores the ray's segment both draw a dark sphere);</li>
 * <li>in the failed unit tests, when they are exactly the tests one mistake fails, with the same
 *     numbers, or exactly two mistakes' together ({@link FailureSignatures}).</li>
 * </ul>
 * Otherwise nothing is named: a wrong name sends a student to fix correct code. A correct submission
 * fails nothing, so it never gets a name.
 */
final class VariantMistakes {
    static final String MATCHES = "Your render matches a known mistake's, whose code ";

    private VariantMistakes() {
    }

    /** The known mistakes of {@code task}, from the variants' own comments. */
    static List<Variant> of(Path tree, int task, Map<String, Integer> studentFiles) throws IOException {
        List<Variant> mistakes = new ArrayList<>();
        for (Variant variant : VariantFolders.in(tree, studentFiles)) {
            if (variant.task == task && variant.knownWrong != null) {
                mistakes.add(variant);
            }
        }
        return mistakes;
    }

    /**
     * The known mistakes the task's results are, by test id: for each failed render test whose
     * image matches a mistake's and whose failed unit tests are that mistake's, {@link #MATCHES} and
     * the mistake; and for failed unit tests, the names {@link FailureSignatures} gives them.
     *
     * @param testsRanIn   where the task's tests ran (the render tests wrote the student's images there)
     * @param taskOutcomes every outcome of the task's tests
     * @param classpath    the instructor's classes and the libraries, for compiling and running the mistakes
     */
    static Map<String, String> named(Path tree, Path testsRanIn, List<TestOutcome> taskOutcomes, List<Variant> mistakes,
            String classpath, Path work, MistakeEvidence evidence) throws IOException, InterruptedException {
        Map<String, String> yourFailures = FailureSignatures.of(taskOutcomes);
        Map<String, FailedRender> yourRenders = new LinkedHashMap<>();
        for (TestOutcome t : taskOutcomes) {
            FailedRender render = t.passed() ? null : FailedRender.of(t, testsRanIn);
            if (render != null) {
                yourRenders.put(t.id(), render);
            }
        }
        if (yourFailures.isEmpty() && yourRenders.isEmpty()) {
            // Only bonus tests failed (a correct textbook form may): no mistake can be named, so none runs.
            return Map.of();
        }
        List<String> scenes = yourRenders.values().stream().map(r -> r.sceneFile).distinct().collect(Collectors.toList());
        Map<String, Map<String, String>> theirFailures = signatures(tree, mistakes, classpath, work, evidence);
        Map<String, String> names = new LinkedHashMap<>(byRenders(tree, yourRenders, scenes, yourFailures.keySet(), theirFailures,
                mistakes, classpath, work, evidence));
        names.putAll(FailureSignatures.named(yourFailures, theirFailures));
        return names;
    }

    /**
     * Runs every mistake's unit tests of the task, a second or so each in a JVM of its own, side by
     * side, one per core (kept in {@code evidence}), and returns each mistake's failure signature by
     * its description (a mistake whose tests could not run is left out).
     */
    private static Map<String, Map<String, String>> signatures(Path tree, List<Variant> mistakes, String classpath, Path work,
            MistakeEvidence evidence) throws InterruptedException {
        List<Optional<Map<String, String>>> measured = inParallel(mistakes,
                mistake -> evidence.failedUnitTests(tree, mistake, classpath, workOf(work, mistake)).orElse(null));
        Map<String, Map<String, String>> theirs = new LinkedHashMap<>();
        for (int i = 0; i < mistakes.size(); i++) {
            String description = mistakes.get(i).knownWrong;
            measured.get(i).ifPresent(signature -> theirs.put(description, signature));
        }
        return theirs;
    }

    /** What a mistake gives when it is run. */
    private interface Run<T> {
        T on(Variant mistake) throws Exception;
    }

    /** {@code run} on each mistake, one per core at once, in the mistakes' order; a run that fails gives empty. */
    private static <T> List<Optional<T>> inParallel(List<Variant> mistakes, Run<T> run) throws InterruptedException {
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, Math.min(mistakes.size(), Runtime.getRuntime().availableProcessors())));
        try {
            List<Future<T>> running = new ArrayList<>();
            for (Variant mistake : mistakes) {
                running.add(pool.submit(() -> run.on(mistake)));
            }
            List<Optional<T>> results = new ArrayList<>();
            for (Future<T> r : running) {
                try {
                    results.add(Optional.ofNullable(r.get()));
                } catch (ExecutionException e) {
                    // That mistake gives no evidence; the others still may.
                    results.add(Optional.empty());
                }
            }
            return results;
        } finally {
            pool.shutdownNow();
        }
    }

    /**
     * Failed render tests whose image matches a mistake's by the render tests' own comparison and
     * whose task fails the same unit tests as that mistake, named by it (the closest render where
     * several do). The picture alone is not enough: two mistakes that both darken a sphere render
     * alike, and a student with a third mistake may render like either.
     */
    private static Map<String, String> byRenders(Path tree, Map<String, FailedRender> yours, List<String> scenes, Set<String> yourFailedTests,
            Map<String, Map<String, String>> theirFailures, List<Variant> mistakes, String classpath, Path work, MistakeEvidence evidence)
            throws IOException, InterruptedException {
        Map<String, String> names = new LinkedHashMap<>();
        if (yours.isEmpty()) {
            return names;
        }
        // Only a mistake that fails the same unit tests can be named; only those render (side by side).
        List<Variant> candidates = mistakes.stream().filter(m -> theirFailures.containsKey(m.knownWrong)
                && theirFailures.get(m.knownWrong).keySet().equals(yourFailedTests)).collect(Collectors.toList());
        if (candidates.isEmpty()) {
            return names;
        }
        List<Optional<Map<String, byte[]>>> theirRenders = inParallel(candidates,
                mistake -> evidence.renders(tree, mistake, scenes, classpath, workOf(work, mistake)));
        Map<String, BufferedImage> yourImages = new LinkedHashMap<>();
        for (Map.Entry<String, FailedRender> entry : yours.entrySet()) {
            yourImages.put(entry.getKey(), ImageIO.read(entry.getValue().yours.toFile()));
        }
        Map<String, Double> closest = new LinkedHashMap<>();
        for (int i = 0; i < candidates.size(); i++) {
            Map<String, byte[]> renders = theirRenders.get(i).orElse(Map.of());
            for (Map.Entry<String, FailedRender> entry : yours.entrySet()) {
                byte[] theirs = renders.get(entry.getValue().sceneFile);
                if (theirs == null) {
                    continue;
                }
                ImageDiff.Result diff = ImageDiff.compare(ImageIO.read(new ByteArrayInputStream(theirs)), yourImages.get(entry.getKey()));
                if (diff.passed() && diff.meanDifference() < closest.getOrDefault(entry.getKey(), Double.POSITIVE_INFINITY)) {
                    closest.put(entry.getKey(), diff.meanDifference());
                    names.put(entry.getKey(), MATCHES + candidates.get(i).knownWrong);
                }
            }
        }
        return names;
    }

    private static Path workOf(Path work, Variant mistake) {
        return work.resolve(mistake.folder.getFileName().toString());
    }
}
