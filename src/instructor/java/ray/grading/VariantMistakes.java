package ray.grading;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
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
        Map<String, String> names = new LinkedHashMap<>();
        Map<String, String> yourFailures = FailureSignatures.of(taskOutcomes);
        names.putAll(byRenders(tree, testsRanIn, taskOutcomes, yourFailures.keySet(), mistakes, classpath, work, evidence));
        if (!yourFailures.isEmpty()) {
            Map<String, Map<String, String>> theirs = new LinkedHashMap<>();
            for (Variant mistake : mistakes) {
                failuresOf(tree, mistake, classpath, work, evidence).ifPresent(signature -> theirs.put(mistake.knownWrong, signature));
            }
            names.putAll(FailureSignatures.named(yourFailures, theirs));
        }
        return names;
    }

    /**
     * Failed render tests whose image matches a mistake's by the render tests' own comparison and
     * whose task fails the same unit tests as that mistake, named by it (the closest render where
     * several do). The picture alone is not enough: two mistakes that both darken a sphere render
     * alike, and a student with a third mistake may render like either.
     */
    private static Map<String, String> byRenders(Path tree, Path testsRanIn, List<TestOutcome> taskOutcomes, Set<String> yourFailedTests,
            List<Variant> mistakes, String classpath, Path work, MistakeEvidence evidence) throws IOException, InterruptedException {
        Map<String, Path> yours = new LinkedHashMap<>();
        Map<String, String> sceneFiles = new LinkedHashMap<>();
        for (TestOutcome t : taskOutcomes) {
            FailedRender render = t.passed() ? null : FailedRender.of(t, testsRanIn);
            if (render != null) {
                yours.put(t.id(), render.yours);
                sceneFiles.put(t.id(), render.sceneFile);
            }
        }
        Map<String, String> names = new LinkedHashMap<>();
        Map<String, Double> closest = new LinkedHashMap<>();
        List<String> scenes = sceneFiles.values().stream().distinct().collect(Collectors.toList());
        for (Variant mistake : yours.isEmpty() ? List.<Variant>of() : mistakes) {
            Map<String, byte[]> theirRenders = evidence.renders(tree, mistake, scenes, classpath, workOf(work, mistake));
            for (Map.Entry<String, Path> entry : yours.entrySet()) {
                byte[] theirs = theirRenders.get(sceneFiles.get(entry.getKey()));
                if (theirs == null) {
                    continue;
                }
                ImageDiff.Result diff = ImageDiff.compare(ImageIO.read(new ByteArrayInputStream(theirs)), ImageIO.read(entry.getValue().toFile()));
                if (diff.passed() && diff.meanDifference() < closest.getOrDefault(entry.getKey(), Double.POSITIVE_INFINITY)
                        && failuresOf(tree, mistake, classpath, work, evidence)
                                .map(theirFailures -> theirFailures.keySet().equals(yourFailedTests)).orElse(false)) {
                    closest.put(entry.getKey(), diff.meanDifference());
                    names.put(entry.getKey(), MATCHES + mistake.knownWrong);
                }
            }
        }
        return names;
    }

    private static Optional<Map<String, String>> failuresOf(Path tree, Variant mistake, String classpath, Path work,
            MistakeEvidence evidence) throws IOException, InterruptedException {
        return evidence.failedUnitTests(tree, mistake, classpath, workOf(work, mistake));
    }

    private static Path workOf(Path work, Variant mistake) {
        return work.resolve(mistake.folder.getFileName().toString());
    }
}
