package ray.endtoend;

import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.Test;
import ray.testing.ProjectFolder;
import ray.testing.StudentTask;

/**
 * docs/grading.md's table of graded scenes says what the table of tasks' scenes grades: every scene
 * there is listed once, in the row of its task, and the table names no scene that is not graded.
 * A scene added to a task's scenes (and so to the render tests) without a line in the students' table fails
 * here, as the four scenes of scenes/hard once went unlisted.
 */
public class GradingDocScenesTest {
    /** A row of the table: "| Task 2 (sphere) | one-sphere, globe |". */
    private static final Pattern ROW = Pattern.compile("\\|\\s*Task (\\d+)\\b[^|]*\\|([^|]*)\\|\\s*(<!--.*-->)?\\s*");
    /** A scene name at the start of a cell entry; anything after it (a remark in parentheses) is not a name. */
    private static final Pattern NAME = Pattern.compile("\\s*([a-z0-9]+(?:-[a-z0-9]+)*)\\b.*", Pattern.DOTALL);

    @Test
    public void theTableOfGradedScenesListsEveryRenderSceneUnderItsTask() throws IOException {
        Path doc = ProjectFolder.resolve("docs", "grading.md");
        Map<String, Integer> listed = new LinkedHashMap<>();
        List<String> problems = new ArrayList<>();
        for (String line : tableOfScenes(Files.readAllLines(doc, StandardCharsets.UTF_8))) {
            Matcher row = ROW.matcher(line);
            if (!row.matches()) {
                problems.add("a row that is not \"| Task N (…) | scene, scene |\": " + line);
                continue;
            }
            int task = Integer.parseInt(row.group(1));
            for (String entry : row.group(2).split(",")) {
                Matcher name = NAME.matcher(entry);
                if (!name.matches()) {
                    problems.add("Task " + task + "'s row has an entry that is no scene name: \"" + entry.strip() + "\"");
                } else if (listed.put(name.group(1), task) != null) {
                    problems.add(name.group(1) + " is listed twice");
                }
            }
        }
        assertTrue("docs/grading.md has no table of graded scenes (a \"| task | scenes |\" header)", !listed.isEmpty() || !problems.isEmpty());
        for (Map.Entry<String, ray.assignment.Task> graded : RenderScenes.tasksOfScenes().entrySet()) {
            Integer row = listed.get(graded.getKey());
            int task = StudentTask.of(graded.getValue().id()).number;
            if (row == null) {
                problems.add(graded.getKey() + " (graded under Task " + task + " in the table of tasks) is missing from the table");
            } else if (row != task) {
                problems.add(graded.getKey() + " is listed under Task " + row + ", but the table of tasks grades it under Task " + task);
            }
        }
        for (String name : listed.keySet()) {
            if (!RenderScenes.tasksOfScenes().containsKey(name)) {
                problems.add(name + " is in the table but not in the table of tasks, so no render test grades it");
            }
        }
        assertTrue("docs/grading.md's table of graded scenes disagrees with the table of tasks: " + String.join("; ", problems),
                problems.isEmpty());
    }

    /** The body rows of the table whose header is "| task | scenes |": the lines after its separator, up to the first that is not a row. */
    private static List<String> tableOfScenes(List<String> lines) {
        List<String> rows = new ArrayList<>();
        for (int n = 0; n < lines.size(); n++) {
            if (lines.get(n).replace(" ", "").equalsIgnoreCase("|task|scenes|")) {
                for (int k = n + 2; k < lines.size() && lines.get(k).startsWith("|"); k++) {
                    rows.add(lines.get(k));
                }
                return rows;
            }
        }
        return rows;
    }
}
