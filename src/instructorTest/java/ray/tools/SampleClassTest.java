package ray.tools;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.grading.ClassSubmission;
import ray.grading.SolutionMarkers;
import ray.grading.StudentFiles;

/**
 * The made-up class is laid out as Gradescope exports one (flat student files per submission
 * folder, the metadata naming each student), mixes every kind of task (solution, correct
 * alternative, known mistake, stub), and the same seed writes the same class.
 */
public class SampleClassTest {
    private static final Path PROJECT = Path.of(".");

    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void aClassIsLaidOutAsGradescopeExportsOne() throws Exception {
        Path out = folder.getRoot().toPath().resolve("class");
        Map<Integer, Integer> drawn = SampleClass.write(PROJECT, out, 40, 7);
        Map<String, Integer> studentFiles = StudentFiles.in(PROJECT);
        long tasks = studentFiles.values().stream().distinct().count();
        assertEquals("every task of every submission is drawn once", 40 * tasks, drawn.values().stream().mapToInt(i -> i).sum());
        for (int kind = 0; kind < 4; kind++) {
            assertTrue("kind " + kind + " drawn in a class of 40: " + drawn, drawn.get(kind) > 0);
        }
        List<ClassSubmission> submissions = ClassSubmission.in(out, null);
        assertEquals(40, submissions.size());
        assertEquals("submission_001", submissions.get(0).id());
        assertEquals("Student 001", submissions.get(0).names());
        assertEquals("student040@example.edu", submissions.get(39).emails());
        Set<String> names = studentFiles.keySet().stream().map(f -> Path.of(f).getFileName().toString()).collect(Collectors.toSet());
        int stubs = 0;
        for (ClassSubmission s : submissions) {
            try (Stream<Path> files = Files.list(s.path())) {
                assertEquals(s.id() + " holds the student files, flat", names,
                        files.map(p -> p.getFileName().toString()).collect(Collectors.toSet()));
            }
            for (String file : studentFiles.keySet()) {
                String text = Files.readString(s.path().resolve(Path.of(file).getFileName()));
                String stub = SolutionMarkers.studentVersion(Files.readString(PROJECT.resolve(file)), file);
                stubs += text.equals(stub) ? 1 : 0;
            }
        }
        assertTrue("some files are the untouched stub", stubs > 0);
    }

    @Test
    public void theSameSeedWritesTheSameClass() throws Exception {
        Path a = folder.getRoot().toPath().resolve("a");
        Path b = folder.getRoot().toPath().resolve("b");
        assertEquals(SampleClass.write(PROJECT, a, 5, 3), SampleClass.write(PROJECT, b, 5, 3));
        try (Stream<Path> files = Files.walk(a)) {
            for (Path file : files.filter(Files::isRegularFile).collect(Collectors.toList())) {
                assertArrayEquals(a.relativize(file).toString(), Files.readAllBytes(file), Files.readAllBytes(b.resolve(a.relativize(file))));
            }
        }
    }
}
