package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertThrows;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/** The handout transformation: solution blocks go, stub lines are uncommented in place, bad markers are reported. */
public class SolutionMarkersTest {
    @Test
    public void dropsSolutionBlocksAndUncommentsStubsKeepingIndentation() {
        String source = String.join("\n",
                "class A {",
                "    int f() {",
                "        // TODO(Task 9): return the answer.",
                "        // BEGIN SOLUTION",
                "        return 42;",
                "        // END SOLUTION",
                "        // STUB: return 0;",
                "    }",
                "}",
                "");
        String expected = String.join("\n",
                "class A {",
                "    int f() {",
                "        // TODO(Task 9): return the answer.",
                "        return 0;",
                "    }",
                "}",
                "");
        assertEquals(expected, SolutionMarkers.studentVersion(source, "A.java"));
    }

    @Test
    public void aFileWithoutMarkersIsUnchanged() {
        String source = "class B {\n    // a comment that mentions STUB: in passing\n}\n";
        assertEquals(source, SolutionMarkers.studentVersion(source, "B.java"));
    }

    @Test
    public void unbalancedMarkersNameTheFileAndLine() {
        IllegalArgumentException unended = assertThrows(IllegalArgumentException.class,
                () -> SolutionMarkers.studentVersion("a\n// BEGIN SOLUTION\nb\n", "C.java"));
        assertEquals("C.java:2: // BEGIN SOLUTION is never ended", unended.getMessage());
        IllegalArgumentException stray = assertThrows(IllegalArgumentException.class,
                () -> SolutionMarkers.studentVersion("a\n  // END SOLUTION\n", "D.java"));
        assertTrue(stray.getMessage(), stray.getMessage().startsWith("D.java:2: // END SOLUTION without"));
        IllegalArgumentException nested = assertThrows(IllegalArgumentException.class,
                () -> SolutionMarkers.studentVersion("// BEGIN SOLUTION\n// BEGIN SOLUTION\n", "E.java"));
        assertTrue(nested.getMessage(), nested.getMessage().startsWith("E.java:2:"));
    }

    @Test
    public void everyStudentFileOfTheRealTreeHasBalancedMarkersAndATask() throws Exception {
        java.util.Map<String, Integer> files = StudentFiles.in(java.nio.file.Path.of("."));
        assertEquals(java.util.Map.of(
                "src/main/java/ray/camera/OrthographicCamera.java", 1,
                "src/main/java/ray/camera/PerspectiveCamera.java", 1,
                "src/main/java/ray/surface/Sphere.java", 2,
                "src/main/java/ray/surface/Triangle.java", 3,
                "src/main/java/ray/surface/Group.java", 4,
                "src/main/java/ray/shading/RepeatTexture.java", 5,
                "src/main/java/ray/shading/ClampTexture.java", 5,
                "src/main/java/ray/surface/Cylinder.java", 6), files);
        for (String file : files.keySet()) {
            String student = SolutionMarkers.studentVersion(java.nio.file.Files.readString(java.nio.file.Path.of(file)), file);
            assertTrue(file, !student.contains("SOLUTION") && !student.contains("// STUB:"));
        }
    }

    /** The student files are the assignment's tasks' files of the table, each with its task's number, as the tests' StudentTask names them. */
    @Test
    public void studentFilesAreTheAssignmentsTasksFiles() {
        java.util.Map<String, Integer> found = StudentFiles.in(java.nio.file.Path.of("."));
        java.util.Map<String, Integer> fromTests = new java.util.TreeMap<>();
        for (ray.testing.StudentTask task : ray.testing.StudentTask.values()) {
            task.files.forEach(f -> fromTests.put(f, task.number));
        }
        assertEquals(fromTests, found);
    }
}
