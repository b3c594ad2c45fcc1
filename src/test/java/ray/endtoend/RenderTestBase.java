package ray.endtoend;

import static org.junit.Assert.fail;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.Test;
import ray.accel.Acceleration;
import ray.image.ImageDiff;
import ray.image.PngReader;
import ray.scene.Scene;
import ray.scene.SceneException;
import ray.testing.NotThisTasksFault;
import ray.testing.StudentTask;

/**
 * A graded render test: renders one shipped scene at its full size with your code and compares
 * it with the reference image in scenes/reference by {@link ImageDiff} (at most
 * {@link ImageDiff#MAX_SHARE} of the pixels may differ by more than
 * {@link ImageDiff#TOLERANCE_LEVELS} levels). A mismatch adds the scene to the report
 * build/reports/render-diff/index.html, with your image, the reference and a heat map.
 *
 * <p>A render runs every task the scene uses, so a failure says whose code is to blame: a scene
 * that does not load is the scene file's fault; a render that throws is reported by
 * {@link ray.testing.StudentTaskRule} under the task whose file threw; and a render that differs
 * names every task the scene uses and those that fail their {@link BasicChecks basic check} (still
 * unfinished). The test summary then lists a differing render under a task whose unit tests fail,
 * or under "Renders" when every task it uses passes them (gradle/test-report.gradle).
 * Only the image decides whether the test passes.
 *
 * <p>Subclasses, one per task, give the scenes (the table of tasks' {@code scenes}), the points and the rule.
 */
public abstract class RenderTestBase {
    /** A whole scene at full size takes about a second with the solution; a stuck loop is stopped here. */
    static final int TIMEOUT_SECONDS = 60;
    /**
     * For a task whose shading calls itself along mirror paths (the 2019 reflection shader, up to 12
     * hits a path): graded, each of those calls crosses between the grader's two processes, and the
     * mirror corridor passed 60 s when graded beside the other tasks' tests on a 2-core machine,
     * where the same render takes 0.4 s outside the grader.
     */
    static final int MIRROR_PATHS_TIMEOUT_SECONDS = 3 * TIMEOUT_SECONDS;
    /**
     * For the bvh task's own scene: graded, every search of a mesh or box is a call into the grader's
     * other process, and every triangle it tests a call back: the solution's tree took 8.5 s graded
     * (on a 2-core machine with a build running beside it) for a render of 0.1 s in one process, and
     * a correct tree that tests twice the triangles must not run out of time.
     */
    static final int FORWARDED_SEARCHES_TIMEOUT_SECONDS = 3 * TIMEOUT_SECONDS;

    private final String scene;

    protected RenderTestBase(String scene) {
        this.scene = scene;
    }

    /**
     * How the render searches boxes and meshes: through the students' tree when the assignment has
     * them write it (so that every render test tests it too), else through the framework's.
     */
    protected Acceleration acceleration() {
        return Acceleration.ofAssignment();
    }

    /** The task this class's scenes count toward: the one the table of tasks gives this class. */
    protected StudentTask task() {
        return StudentTask.ofTestClass(getClass());
    }

    @Test
    public void rendersLikeTheReference() throws Exception {
        Path file = RenderScenes.fileOf(scene);
        Path referenceFile = RenderScenes.referenceOf(scene);
        // Read by their absolute paths, named in messages relative to the project (scenes/x.xml).
        Path shown = RenderScenes.shown(file);
        Path referenceShown = RenderScenes.shown(referenceFile);
        if (!Files.exists(file)) {
            throw new NotThisTasksFault("the scene " + shown + " is missing; restore it from the handout");
        }
        if (!Files.exists(referenceFile)) {
            throw new NotThisTasksFault("no reference image " + referenceShown + " for " + shown + "; restore it from the handout");
        }
        Scene loaded;
        try {
            loaded = RenderScenes.load(file);
        } catch (SceneException e) {
            throw new NotThisTasksFault("the scene does not load: " + e.messageNaming(RenderScenes.shown(e.file()))
                    + "\n    Fix the scene file, or restore it from the handout; this test judges your code once it loads.");
        }
        BufferedImage reference = PngReader.read(referenceFile);
        // An exception from a student file propagates: StudentTaskRule reports it under the task whose
        // file threw, with the same first line as that task's unit tests, so the summary names it once.
        RenderScenes.Rendered rendered = RenderScenes.renderWithKinds(loaded, acceleration());
        BufferedImage yours = rendered.image();
        ImageDiff.Result result = ImageDiff.compare(reference, yours);
        RenderDiffReport.ran(getClass(), scene, result.passed());
        if (result.passed()) {
            return;
        }
        // What the differing pixels show in this render and the worst of them, right under the first
        // line; the tasks the scene uses and the report last. The page's entry says the same.
        List<String> pixels = DifferingPixels.lines(result, rendered.kinds(), shown);
        String uses = usesLine(loaded);
        List<String> findings = new ArrayList<>(pixels);
        // A microfacet scene: which of the BRDF's factors, each rendered alone, parts from the reference's.
        List<MicrofacetFactorViews.View> factors = loaded.hasMicrofacetShader()
                ? MicrofacetFactorViews.of(loaded, referenceFile.getParent(), scene) : List.of();
        if (!factors.isEmpty()) {
            findings.add(MicrofacetFactorViews.line(factors));
            pixels = new ArrayList<>(pixels);
            pixels.add(MicrofacetFactorViews.line(factors));
        }
        findings.add(uses);
        String report = RenderDiffReport.add(getClass(), scene, file, task(), result, yours, reference, String.join("\n", findings),
                factors);
        StringBuilder differs = new StringBuilder(shown + " does not look like " + referenceShown + ": " + result.summary() + ".");
        pixels.forEach(line -> differs.append("\n    ").append(line));
        String see = "\n    " + uses + "\n    See your image, the reference and where they differ in " + report;
        List<String> unfinished = new ArrayList<>();
        List<String> unfinishedTasks = new ArrayList<>();
        for (StudentTask other : BasicChecks.tasksOf(loaded)) {
            if (other == task()) {
                continue;
            }
            String problem = BasicChecks.problem(other, loaded);
            if (problem != null) {
                unfinished.add(other.label() + ": " + problem);
                unfinishedTasks.add(other.label());
            }
        }
        String own = BasicChecks.problem(task(), loaded);
        if (!unfinished.isEmpty() && own == null) {
            // The first line says it all, since a test summary may show only that line.
            throw new NotThisTasksFault(shown + " also needs " + inWords(unfinishedTasks)
                    + (unfinished.size() == 1 ? ", which does" : ", which do") + " not work yet: this test judges your " + task().label() + " code once "
                    + (unfinished.size() == 1 ? "it works" : "they work") + ".\n    " + differs + "\n    Your " + task().label()
                    + " code passes its basic check; these fail theirs:\n      " + String.join("\n      ", unfinished) + see);
        }
        StringBuilder message = new StringBuilder(differs);
        if (own != null) {
            message.append("\n    Your ").append(task().label()).append(" code fails a basic check: ").append(sentence(own));
        }
        if (!unfinished.isEmpty()) {
            message.append("\n    Unfinished too: ").append(sentence(String.join("; ", unfinished)));
        }
        fail(message + see);
    }

    /**
     * "The scene uses Task 1 (Camera rays), Task 2 (Sphere) and Task 4 (Group)." The test summary reads
     * this line to list a differing render under a task whose unit tests fail, or under "Renders" when
     * none does (gradle/test-report.gradle), so its wording is part of that contract.
     */
    static String usesLine(Scene scene) {
        List<String> labels = new ArrayList<>();
        for (StudentTask t : BasicChecks.tasksOf(scene)) {
            labels.add(t.label());
        }
        return "The scene uses " + inWords(labels) + ".";
    }

    /** The text with a full stop, unless it already ends a sentence ("is it still the stub?"). */
    private static String sentence(String text) {
        return text.matches("(?s).*[.?!]$") ? text : text + ".";
    }

    /** "A", "A and B", "A, B and C". */
    private static String inWords(List<String> items) {
        int last = items.size() - 1;
        return last == 0 ? items.get(0) : String.join(", ", items.subList(0, last)) + " and " + items.get(last);
    }
}
