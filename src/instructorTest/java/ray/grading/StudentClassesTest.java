package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * A handed-in file may define its public class and what is nested in it; any other class it makes
 * (one named like a test helper, one in another package) is refused with a line naming it.
 */
public class StudentClassesTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private static final List<String> FILES = List.of("src/main/java/ray/surface/Sphere.java");

    /** A folder of compiled classes with these (empty) class files, as javac writes them. */
    private Path compiled(String... classFiles) throws Exception {
        Path classes = folder.newFolder().toPath();
        for (String file : classFiles) {
            Path p = classes.resolve(file);
            Files.createDirectories(p.getParent());
            Files.write(p, new byte[] {(byte) 0xca, (byte) 0xfe, (byte) 0xba, (byte) 0xbe});
        }
        return classes;
    }

    @Test
    public void theFilesClassAndItsNestedLocalAndAnonymousClassesAreFine() throws Exception {
        assertNull(StudentClasses.refused(compiled("ray/surface/Sphere.class", "ray/surface/Sphere$Roots.class",
                "ray/surface/Sphere$1.class", "ray/surface/Sphere$1Local.class"), FILES));
    }

    @Test
    public void aSecondTopLevelClassNamedLikeATestHelperIsRefused() throws Exception {
        assertEquals("the class ray.surface.HitAsserts must not be defined there: a file you hand in may hold only its public class"
                + " and the classes nested in it. Move it inside that class (as a static nested class), or into your methods.",
                StudentClasses.refused(compiled("ray/surface/Sphere.class", "ray/surface/HitAsserts.class"), FILES));
    }

    @Test
    public void classesInAnotherPackageAreRefusedAllNamed() throws Exception {
        String why = StudentClasses.refused(compiled("ray/surface/Sphere.class", "ray/testing/Points.class",
                "ray/shading/TextureLookups$1.class", "ray/surface/package-info.class"), FILES);
        assertEquals("the classes ray.shading.TextureLookups$1, ray.surface.package-info, ray.testing.Points must not be defined there:"
                + " a file you hand in may hold only its public class and the classes nested in it. Move them inside that class"
                + " (as a static nested class), or into your methods.", why);
    }
}
