package ray.testing;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * {@link ProjectFolder#find}'s search, on folder trees made here: the working folder, then its
 * parents, then the parents of the test classes' folder as each IDE lays it out, and a folder needs
 * both scenes/ and settings.gradle to count. {@link RenderTestsFromOtherFoldersTest} runs the real
 * thing in another JVM.
 */
public class ProjectFolderTest {
    @Rule
    public final TemporaryFolder temporary = new TemporaryFolder();

    /** A folder that looks like the project: scenes/ and settings.gradle. */
    private Path project(String name) throws IOException {
        Path folder = Files.createDirectories(temporary.getRoot().toPath().resolve(name));
        Files.createDirectories(folder.resolve("scenes"));
        Files.writeString(folder.resolve("settings.gradle"), "rootProject.name = 'ray1'\n");
        return folder;
    }

    private Path folder(String path) throws IOException {
        return Files.createDirectories(temporary.getRoot().toPath().resolve(path));
    }

    @Test
    public void theWorkingFolderWhenItIsTheProject() throws Exception {
        Path project = project("ray1");
        assertEquals(project, ProjectFolder.find(project, null));
    }

    @Test
    public void theNearestProjectAboveTheWorkingFolder() throws Exception {
        // A project inside another folder that looks like one: the nearer wins, as for git.
        project("outer");
        Path inner = project("outer/course/ray1");
        Path working = folder("outer/course/ray1/src/test/java");
        assertEquals(inner, ProjectFolder.find(working, null));
    }

    @Test
    public void aFolderWithScenesAloneIsNotTheProject() throws Exception {
        // A student's own folder of scenes (or scenes/ itself, with its subfolders) is not the project.
        Path project = project("ray1");
        Path mine = folder("ray1/my work/scenes");
        assertEquals(project, ProjectFolder.find(mine.getParent(), null));
        Path settingsAlone = folder("elsewhere");
        Files.writeString(settingsAlone.resolve("settings.gradle"), "");
        assertFalse(ProjectFolder.isProject(settingsAlone));
    }

    @Test
    public void theTestClassesFolderOfEachBuildWhenTheWorkingFolderIsOutside() throws Exception {
        Path project = project("ray1");
        Path working = folder("workspace");
        // Gradle, Eclipse and VS Code (bin/test), IntelliJ's own build.
        for (String classes : new String[] {"build/classes/java/test", "bin/test", "out/test/classes"}) {
            assertEquals(classes, project, ProjectFolder.find(working, folder("ray1/" + classes)));
        }
    }

    @Test
    public void theWorkingFolderComesBeforeTheClassesFolder() throws Exception {
        Path here = project("here");
        project("there");
        assertEquals(here, ProjectFolder.find(here, folder("there/build/classes/java/test")));
    }

    @Test
    public void noProjectFailsWithOneLineSayingWhatWasLookedForAndWhere() throws Exception {
        Path working = folder("workspace");
        Path classes = folder("copied/classes");
        try {
            ProjectFolder.find(working, classes);
            fail("found a project where there is none");
        } catch (NotThisTasksFault e) {
            String message = e.getMessage();
            assertEquals(message, 1, message.lines().count());
            assertTrue(message, message.startsWith("cannot find the ray1 project folder (the one with scenes/ and settings.gradle)"));
            assertTrue(message, message.contains("the working folder " + working));
            assertTrue(message, message.contains("the test classes' folder " + classes));
        }
    }

    @Test
    public void underGradleItIsTheWorkingFolder() {
        // build.gradle runs the tests in the project folder: the search must stop there at once.
        Path project = ProjectFolder.get();
        assertEquals(Path.of("").toAbsolutePath(), project);
        assertTrue(Files.isRegularFile(ProjectFolder.resolve("scenes", "one-sphere.xml")));
    }
}
