package ray.grading;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A failed render test as the grader finds it after the run: the scene file its message names, and
 * the pictures the test wrote into the grading tree's render-diff report (the student's render, the
 * reference and their heat map), which feedback ({@link RenderFeedback}) and the search for a known
 * mistake ({@link VariantMistakes}) both read.
 */
final class FailedRender {
    private static final Pattern SCENE = Pattern.compile("^(\\S+\\.xml) does not look like", Pattern.MULTILINE);
    private static final Pattern PARAMETER = Pattern.compile("\\[([^\\]]+)\\]$");

    /** The scene file as the message names it ("scenes/one-sphere.xml"). */
    final String sceneFile;
    final Path yours;
    final Path reference;
    final Path difference;

    private FailedRender(String sceneFile, Path folder, String scene) {
        this.sceneFile = sceneFile;
        this.yours = folder.resolve(scene + "-yours.png");
        this.reference = folder.resolve(scene + "-reference.png");
        this.difference = folder.resolve(scene + "-diff.png");
    }

    /** {@code t} as a failed render test whose render exists under {@code tree}, or null for any other outcome. */
    static FailedRender of(TestOutcome t, Path tree) {
        if (t.passed() || !t.isRenderTest()) {
            return null;
        }
        Matcher parameter = PARAMETER.matcher(t.method());
        Matcher scene = SCENE.matcher(t.message().replaceFirst("^\\[[^\\]]*\\] ", ""));
        if (!parameter.find() || !scene.find()) {
            return null;
        }
        String simpleName = t.className().substring(t.className().lastIndexOf('.') + 1);
        FailedRender failed = new FailedRender(scene.group(1), tree.resolve("build/reports/render-diff").resolve(simpleName),
                parameter.group(1));
        return Files.isRegularFile(failed.yours) ? failed : null;
    }
}
