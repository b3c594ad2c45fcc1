package ray.grading;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.grading.VariantFolders.Variant;

/**
 * The known mistakes' renders that gradeAll keeps for the class: a mistake renders a scene once, in
 * the tree it was given (never in the grading's own tree), and every later grading gets the same
 * picture without rendering again.
 */
public class MistakeEvidenceTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private static final Path PROJECT = Path.of(".").toAbsolutePath().normalize();
    /** The libraries, as the tests run with them. */
    private static final String LIBRARIES = Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
            .filter(p -> p.endsWith(".jar")).collect(Collectors.joining(File.pathSeparator));

    @Test(timeout = 300_000)
    public void eachMistakeRendersEachSceneOnceForTheClass() throws Exception {
        Map<String, Integer> studentFiles = StudentFiles.in(PROJECT);
        Variant farRoot = VariantFolders.in(PROJECT, studentFiles).stream()
                .filter(v -> v.folder.getFileName().toString().equals("sphere-far-root")).findFirst().orElseThrow();
        // The class's compiled tree, which the mistakes run in.
        CompiledTree tree = CompiledTree.build(PROJECT, folder.getRoot().toPath().resolve("compiled"), LIBRARIES);
        MistakeEvidence renders = new MistakeEvidence(tree.root(), LIBRARIES);
        // The grading's tree does not even exist: the mistake renders in the project it was given.
        Path gradingTree = folder.getRoot().toPath().resolve("no-such-tree");
        Path first = folder.getRoot().toPath().resolve("first");
        Map<String, byte[]> once = renders.renders(gradingTree, farRoot, List.of("scenes/one-sphere.xml"), "not used", first);
        assertEquals(List.of("scenes/one-sphere.xml"), List.copyOf(once.keySet()));
        assertTrue(Files.isRegularFile(first.resolve("renders/one-sphere.png")));
        assertArrayEquals(Files.readAllBytes(first.resolve("renders/one-sphere.png")), once.get("scenes/one-sphere.xml"));

        Path second = folder.getRoot().toPath().resolve("second");
        Map<String, byte[]> again = renders.renders(gradingTree, farRoot, List.of("scenes/one-sphere.xml"), "not used", second);
        assertFalse("rendered again", Files.exists(second));
        assertArrayEquals(once.get("scenes/one-sphere.xml"), again.get("scenes/one-sphere.xml"));
        assertFalse(Files.exists(gradingTree));
    }

    /**
     * A mistake in one file of a task (RepeatTexture) runs with the solution's other files of that task
     * (ClampTexture), as a student's submission with that one mistake would: it fails the repeat
     * tests only, so its failures can be matched with a student's.
     */
    @Test(timeout = 300_000)
    public void aMistakeInOneFileRunsBesideTheSolutionsOtherFiles() throws Exception {
        Variant roundTwice = VariantFolders.in(PROJECT, StudentFiles.in(PROJECT)).stream()
                .filter(v -> v.folder.getFileName().toString().equals("texture-round-twice")).findFirst().orElseThrow();
        assertEquals(List.of("RepeatTexture.java"), roundTwice.sources.stream().map(p -> p.getFileName().toString()).collect(Collectors.toList()));
        CompiledTree tree = CompiledTree.build(PROJECT, folder.getRoot().toPath().resolve("compiled"), LIBRARIES);
        MistakeEvidence evidence = new MistakeEvidence(tree.root(), LIBRARIES);
        Map<String, String> failed = evidence.failedUnitTests(folder.getRoot().toPath().resolve("no-such-tree"), roundTwice, "not used",
                folder.getRoot().toPath().resolve("round-twice")).orElseThrow();
        assertTrue(failed.toString(), failed.containsKey("ray.shading.RepeatTextureTest#theImagesEdgesWrapAsTheCourseDoes"));
        assertTrue(failed.toString(), failed.keySet().stream().allMatch(id -> id.startsWith("ray.shading.RepeatTextureTest#")
                || id.startsWith("ray.hidden.TexturesHiddenTest#")));
        assertFalse(failed.toString(), failed.values().stream().anyMatch(message -> message.contains("ClampTexture.getTexColor")
                || message.contains("ClampTexture on")));
    }
}
