package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * gradeAll's shared compiled tree, on a project of two classes: it compiles once, each grading gets
 * a copy that is the tree to the byte, what a grading does to its copy leaves the tree as it was,
 * and a change to the tree itself is noticed for good. (GradeAllTest grades real submissions on it.)
 */
public class CompiledTreeTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private Path project(String aClass) throws Exception {
        Path project = folder.getRoot().toPath().resolve("project");
        Files.createDirectories(project.resolve("src/main/java/p"));
        Files.createDirectories(project.resolve("scenes"));
        Files.writeString(project.resolve("settings.gradle"), "rootProject.name = 'ray1'\n");
        Files.writeString(project.resolve("scenes/one.xml"), "<scene/>\n");
        Files.writeString(project.resolve("src/main/java/p/A.java"), aClass);
        Files.writeString(project.resolve("src/main/java/p/B.java"), "package p;\nclass B { int b() { return new A().a(); } }\n");
        return project;
    }

    @Test
    public void aGradingsCopyIsTheTreeAndWhatItDoesThereLeavesTheTreeAlone() throws Exception {
        Path root = folder.getRoot().toPath().resolve("trees/tree-1");
        CompiledTree tree = CompiledTree.build(project("package p;\nclass A { int a() { return 1; } }\n"), root, "");
        assertEquals(root, tree.root());
        assertTrue(Files.isRegularFile(root.resolve("classes/p/A.class")) && Files.isRegularFile(root.resolve("classes/p/B.class")));
        assertTrue(Files.isRegularFile(root.resolve("scenes/one.xml")) && Files.isRegularFile(root.resolve("settings.gradle")));
        String fingerprint = CompiledTree.fingerprint(root);

        Path copy = folder.getRoot().toPath().resolve("submission/work-1/instructor");
        tree.copyTo(copy);
        assertEquals("the copy is the tree", fingerprint, CompiledTree.fingerprint(copy));
        // The grading's tests write their report and whatever student code likes into the copy.
        Files.writeString(copy.resolve("classes/p/A.class"), "not a class");
        Files.createDirectories(copy.resolve("build/reports/render-diff"));
        Files.delete(copy.resolve("scenes/one.xml"));
        assertTrue(tree.unchanged());
        assertEquals(fingerprint, CompiledTree.fingerprint(root));
        // The next grading's copy is the tree again.
        Path next = folder.getRoot().toPath().resolve("next/work-2/instructor");
        tree.copyTo(next);
        assertEquals(fingerprint, CompiledTree.fingerprint(next));
    }

    @Test
    public void aChangeToTheTreeItselfIsNoticedForGood() throws Exception {
        Path root = folder.getRoot().toPath().resolve("tree");
        CompiledTree tree = CompiledTree.build(project("package p;\nclass A { int a() { return 1; } }\n"), root, "");
        String fingerprint = CompiledTree.fingerprint(root);
        Path a = root.resolve("classes/p/A.class");
        byte[] compiled = Files.readAllBytes(a);
        Files.write(a, new byte[] {(byte) 0xca, (byte) 0xfe});
        assertFalse(tree.unchanged());
        // Put back as it was: a grading may have used it changed meanwhile, so it stays spoiled.
        Files.write(a, compiled);
        assertEquals(fingerprint, CompiledTree.fingerprint(root));
        assertFalse(tree.unchanged());
        // The fingerprint sees a file added, a file emptied, and a folder added.
        Files.writeString(root.resolve("scenes/two.xml"), "");
        String added = CompiledTree.fingerprint(root);
        assertNotEquals(fingerprint, added);
        Files.writeString(root.resolve("scenes/one.xml"), "");
        assertNotEquals(added, CompiledTree.fingerprint(root));
        String emptied = CompiledTree.fingerprint(root);
        Files.createDirectories(root.resolve("scenes/more"));
        assertNotEquals(emptied, CompiledTree.fingerprint(root));
    }

    @Test
    public void aTreeThatDoesNotCompileIsAnErrorThatLeavesNothingBehind() throws Exception {
        Path root = folder.getRoot().toPath().resolve("tree");
        try {
            CompiledTree.build(project("package p;\nclass A { int a() { return 1 } }\n"), root, "");
            fail("compiled");
        } catch (IllegalStateException e) {
            assertTrue(e.getMessage(), e.getMessage().startsWith("the instructor's tree does not compile:\n"));
            assertTrue(e.getMessage(), e.getMessage().contains("src/main/java/p/A.java:2: error: ';' expected"));
        }
        assertFalse(Files.exists(root));
    }

    @Test
    public void eachTasksTestsAreListedOnceForEveryGrading() throws Exception {
        CompiledTree tree = CompiledTree.build(project("package p;\nclass A { int a() { return 1; } }\n"),
                folder.getRoot().toPath().resolve("tree"), "");
        AtomicInteger listed = new AtomicInteger();
        TestOutcome test = new TestOutcome("p.ATest#a", "p.ATest", "a", 2, "A", 1, false, "visible", false, "not run", 0);
        CompiledTree.Lister lister = () -> {
            listed.incrementAndGet();
            return List.of(test);
        };
        assertEquals(List.of(test), tree.tests(2, lister));
        assertEquals(List.of(test), tree.tests(2, lister));
        assertEquals(1, listed.get());
        tree.tests(null, lister);
        assertEquals("another task is listed for itself", 2, listed.get());
    }
}
