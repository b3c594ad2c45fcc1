package ray.tools;

import static org.junit.Assert.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * A package holds what git tracks: an instructor's untracked scratch file stays out of the
 * autograder and the handout, an edit to a tracked file goes in, a tracked file deleted from the
 * working tree is skipped; a project that is not a checkout ships every file.
 */
public class TrackedFilesTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    @Test(timeout = 120_000)
    public void aCheckoutShipsItsTrackedFilesAsTheyAreInTheWorkingTree() throws Exception {
        Path project = folder.getRoot().toPath();
        write(project, "src/main/A.java", "class A {}");
        write(project, "src/main/Gone.java", "class Gone {}");
        write(project, "scenes/a.xml", "<scene/>");
        git(project, "init", "-q");
        git(project, "add", "src", "scenes");
        git(project, "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "-m", "first");
        write(project, "src/main/Scratch.java", "class Scratch { /* solution notes */ }");
        write(project, "src/main/A.java", "class A { int edited; }");
        Files.delete(project.resolve("src/main/Gone.java"));

        assertEquals(List.of("src/main/A.java"), names(project, TrackedFiles.under(project, "src")));
        assertEquals(List.of("scenes/a.xml", "src/main/A.java"), names(project, TrackedFiles.under(project, ".")));
        assertEquals("class A { int edited; }", Files.readString(TrackedFiles.under(project, "src").get(0)));
    }

    @Test
    public void aFolderThatIsNoCheckoutShipsEveryFile() throws Exception {
        Path project = folder.getRoot().toPath();
        write(project, "src/main/B.java", "class B {}");
        write(project, "src/main/A.java", "class A {}");
        write(project, "README.md", "hi");
        assertEquals(List.of("src/main/A.java", "src/main/B.java"), names(project, TrackedFiles.under(project, "src")));
        assertEquals(List.of("README.md", "src/main/A.java", "src/main/B.java"), names(project, TrackedFiles.under(project, ".")));
    }

    private static List<String> names(Path project, List<Path> files) {
        return files.stream().map(f -> project.relativize(f).toString().replace('\\', '/')).collect(Collectors.toList());
    }

    private static void write(Path project, String name, String text) throws Exception {
        Files.createDirectories(project.resolve(name).getParent());
        Files.writeString(project.resolve(name), text);
    }

    private static void git(Path project, String... args) throws Exception {
        String[] command = new String[args.length + 3];
        command[0] = "git";
        command[1] = "-C";
        command[2] = project.toString();
        System.arraycopy(args, 0, command, 3, args.length);
        Process p = new ProcessBuilder(command).inheritIO().start();
        if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0) {
            throw new AssertionError("git " + String.join(" ", args) + " failed");
        }
    }
}
