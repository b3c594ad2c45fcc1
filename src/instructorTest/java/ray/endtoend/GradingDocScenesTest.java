package ray.endtoend;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.Test;
import ray.assignment.Assignment;
import ray.testing.ProjectFolder;
import ray.tools.AssignmentDocs;

/**
 * docs/grading.md's table of graded scenes is written by the handout from the table of tasks (its
 * {@code <!-- TABLE scenes -->} block), so a student's copy always lists what the render tests
 * grade. The instructor's copy, which the handout replaces, must read the same for the default
 * preset, or the instructor would read a stale table.
 */
public class GradingDocScenesTest {
    @Test
    public void theInstructorsTableOfScenesIsTheOneTheHandoutWrites() throws Exception {
        Path doc = ProjectFolder.resolve("docs", "grading.md");
        List<String> lines = Files.readAllLines(doc, StandardCharsets.UTF_8);
        int begin = lines.indexOf("<!-- TABLE scenes -->");
        int end = lines.indexOf("<!-- END TABLE -->");
        assertTrue("docs/grading.md has no <!-- TABLE scenes --> block", begin >= 0 && end > begin);
        String block = String.join("\n", lines.subList(begin, end + 1));
        String written = AssignmentDocs.compose(block, "docs/grading.md", Assignment.preset(Assignment.DEFAULT_PRESET));
        assertEquals("docs/grading.md's table of scenes, as the handout writes it for the default preset",
                written, String.join("\n", lines.subList(begin + 1, end)));
    }
}
