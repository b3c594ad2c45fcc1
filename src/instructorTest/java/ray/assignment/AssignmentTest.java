package ray.assignment;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.io.IOException;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/** The table of tasks and the assignment files that choose from it: numbers, extra credit, and the one-line errors. */
public class AssignmentTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private static List<String> ids(Assignment a) {
        return a.tasks().stream().map(Task::id).collect(Collectors.toList());
    }

    private static Assignment read(String text, Map<String, String> overrides) {
        return Assignment.read(new StringReader(text), "assignment.properties", TaskTable.standard(), overrides);
    }

    @Test
    public void theIntersectionsPresetIsTodaysSixTasksNumberedAsEver() {
        Assignment a = Assignment.preset("intersections");
        assertEquals(List.of("camera-rays", "sphere", "triangle", "group", "textures", "cylinder"), ids(a));
        assertEquals(2, a.number("sphere"));
        assertEquals(4, a.number("group"));
        assertEquals(6, a.number("cylinder"));
        assertTrue(a.isExtraCredit("cylinder"));
        assertFalse(a.isExtraCredit("sphere"));
        assertEquals("Task 3 (Triangle)", a.label("triangle"));
        assertEquals("TODO(Task 5)", a.todo("textures"));
        assertEquals("2017", a.course());
    }

    @Test
    public void theCourse2017PresetNumbersTheTasksInTheCoursesOrder() {
        Assignment a = Assignment.preset("course-2017");
        assertEquals(List.of("camera-rays", "ray-color", "group", "sphere", "lighting", "triangle", "textures", "cylinder"), ids(a));
        assertEquals(3, a.number("group"));
        assertEquals(4, a.number("sphere"));
        assertEquals(5, a.number("lighting"));
        assertTrue(a.isExtraCredit("cylinder"));
    }

    @Test
    public void withoutAnAssignmentFileTheBuildUsesTheDefaultPreset() throws IOException {
        assertEquals(Assignment.preset(Assignment.DEFAULT_PRESET), Assignment.resolve(folder.getRoot().toPath(), null, Map.of()));
    }

    @Test
    public void aFileChoosesTasksAndTheirOrderAndTheOthersAreNotChosen() {
        Assignment a = read("tasks = group, sphere\n", Map.of());
        assertEquals(List.of("group", "sphere"), ids(a));
        assertEquals(1, a.number("group"));
        assertEquals(2, a.number("sphere"));
        assertEquals(0, a.number("triangle"));
        assertFalse(a.isChosen("triangle"));
        assertEquals("Triangle", a.label("triangle"));
        // Extra credit where the file does not say: the chosen tasks the table marks so (none here).
        assertFalse(a.isExtraCredit("cylinder"));
        assertEquals("group", a.named("1").orElseThrow().id());
        assertEquals("sphere", a.named("sphere").orElseThrow().id());
        assertTrue(a.named("3").isEmpty());
        assertTrue(a.named("triangle").isEmpty());
    }

    @Test
    public void aPresetWithOverridesForOneRun() {
        Assignment a = read("preset = intersections\n", Map.of("tasks", "sphere, triangle, cylinder"));
        assertEquals(List.of("sphere", "triangle", "cylinder"), ids(a));
        assertTrue("the preset's extra credit stays", a.isExtraCredit("cylinder"));
        Assignment required = read("preset = intersections\nextraCredit =\n", Map.of());
        assertFalse("an empty extraCredit makes every chosen task required", required.isExtraCredit("cylinder"));
    }

    @Test
    public void theFileTextReadsBackAsTheSameAssignment() {
        for (String preset : Assignment.presetNames()) {
            Assignment a = Assignment.preset(preset);
            assertEquals(preset, a, read(a.toFileText("a comment\non two lines"), Map.of()));
        }
        Assignment custom = read("tasks = textures, sphere\nextraCredit = textures\n", Map.of());
        assertEquals(custom, read(custom.toFileText(""), Map.of()));
    }

    @Test
    public void eachMistakeInAnAssignmentFileIsOneLineNamingTheFileAndWhatWasExpected() {
        refused("tasks = sphere, spheres\n", Map.of(),
                "assignment.properties: there is no task \"spheres\"; the tasks are camera-rays, ray-color, group, sphere, lighting, brdfs, reflection, triangle, textures, microfacet, cylinder, bvh");
        refused("tasks = sphere, sphere\n", Map.of(), "assignment.properties: the task sphere is chosen twice");
        refused("tasks = sphere\nhint = goal\n", Map.of(),
                "assignment.properties: unknown key \"hint\"; expected preset, tasks, extraCredit, hints, course, hints.ID or points.ID");
        refused("preset = course-2042\n", Map.of(),
                "assignment.properties: preset = course-2042 is no preset; the presets are intersections, course-2017, course-2018, course-2019, course-2019-part2");
        refused("tasks = sphere\ncourse = 2018\n", Map.of(),
                "assignment.properties: course = 2018; ray1 renders with the course's conventions of 2017, 2019");
        refused("tasks = sphere, lighting\ncourse = 2019\n", Map.of(), "assignment.properties: the task lighting is written by the course's"
                + " 2017 conventions, and this assignment's course is 2019; choose it with course = 2017");
        refused("tasks = sphere, brdfs\n", Map.of(), "assignment.properties: the task brdfs is written by the course's"
                + " 2019 conventions, and this assignment's course is 2017; choose it with course = 2019");
        refused("tasks = cylinder\nextraCredit = cylinder\n", Map.of(),
                "assignment.properties: every chosen task is extra credit; at least one must be required");
        refused("tasks =\n", Map.of(), "assignment.properties: no tasks; give `tasks = id, id, …` from camera-rays, ray-color, group,"
                + " sphere, lighting, brdfs, reflection, triangle, textures, microfacet, cylinder, bvh");
        refused("preset = intersections\n", Map.of("tasks", "sphere,kdtree"),
                "assignment.properties with tasks given: there is no task \"kdtree\"; the tasks are camera-rays, ray-color, group, sphere,"
                        + " lighting, brdfs, reflection, triangle, textures, microfacet, cylinder, bvh");
    }

    @Test
    public void hintLevelsForTheAssignmentAndForOneTask() {
        Assignment a = read("tasks = sphere, triangle\nhints = steps\nhints.triangle = goal\n", Map.of());
        assertEquals(HintLevel.STEPS, a.hints("sphere"));
        assertEquals(HintLevel.GOAL, a.hints("triangle"));
        assertEquals(a, read(a.toFileText(""), Map.of()));
        assertEquals(HintLevel.FORMULAS, Assignment.preset("intersections").hints("sphere"));
        assertEquals("the course's own TODOs said the goal alone", HintLevel.GOAL, Assignment.preset("course-2017").hints("sphere"));
        assertEquals(HintLevel.GOAL, read("preset = intersections\n", Map.of("hints", "goal")).hints("group"));
        refused("tasks = sphere\nhints = lots\n", Map.of(), "assignment.properties: hints = lots; expected goal, steps or formulas");
        refused("tasks = sphere\nhints.spheres = goal\n", Map.of(), "assignment.properties: hints.spheres names no task; the tasks are"
                + " camera-rays, ray-color, group, sphere, lighting, brdfs, reflection, triangle, textures, microfacet, cylinder, bvh");
    }

    @Test
    public void aTaskChosenWithoutTheTaskItBuildsOnIsRefusedNamingBoth() throws IOException {
        TaskTable table = TaskTable.parse(new StringReader(String.join("\n",
                "tasks = bounds, tree",
                "bounds.title = Bounding boxes", "bounds.files = ray/accel/Bounds.java", "bounds.tests = ray.accel.Bounds*",
                "tree.title = The tree", "tree.files = ray/accel/Tree.java", "tree.tests = ray.accel.Tree*", "tree.needs = bounds")),
                "tasks.properties");
        try {
            Assignment.read(new StringReader("tasks = tree\n"), "assignment.properties", table, Map.of());
            fail("accepted a task without the one it builds on");
        } catch (AssignmentException e) {
            assertEquals("assignment.properties: the task tree builds on bounds, which is not chosen; choose both or neither", e.getMessage());
        }
        Assignment both = Assignment.read(new StringReader("tasks = bounds, tree\n"), "assignment.properties", table, Map.of());
        assertEquals(2, both.number("tree"));
    }

    @Test
    public void aBrokenTableIsOneLineNamingTheKey() {
        tableRefused("tasks = a\na.files = x.java\na.tests = x.*\n", "tasks.properties: a.title is missing");
        tableRefused("tasks = a\na.title = A\na.files = x.java\na.tests = x.*\na.needs = b\n",
                "tasks.properties: a.needs names \"b\", which is no task of the table");
        tableRefused("tasks = a\na.title = A\na.files = x.java\na.tests = x.*\na.extraCredit = yes\n",
                "tasks.properties: a.extraCredit is \"yes\"; expected true or false");
        tableRefused("tasks = a\na.title = A\na.files = x.java\na.tests = x.*\nb.title = B\n",
                "tasks.properties: b.title belongs to no task of the `tasks` line");
    }

    @Test
    public void anAssignmentFileOrPresetGivenForOneRun() throws IOException {
        Path project = folder.getRoot().toPath();
        Files.writeString(project.resolve("assignment.properties"), "preset = course-2017\n", StandardCharsets.UTF_8);
        Files.writeString(project.resolve("short.properties"), "tasks = sphere, group\n", StandardCharsets.UTF_8);
        assertEquals(Assignment.preset("course-2017"), Assignment.resolve(project, null, Map.of()));
        assertEquals(Assignment.preset("intersections"), Assignment.resolve(project, "intersections", Map.of()));
        assertEquals(List.of("sphere", "group"), ids(Assignment.resolve(project, "short.properties", Map.of())));
        assertEquals(List.of("triangle"), ids(Assignment.resolve(project, null, Map.of("tasks", "triangle"))));
        try {
            Assignment.resolve(project, "nowhere.properties", Map.of());
            fail();
        } catch (AssignmentException e) {
            assertEquals("-Passignment=nowhere.properties: no such preset or file; the presets are intersections, course-2017, course-2018, course-2019, course-2019-part2", e.getMessage());
        }
    }

    /** The shipped table: every student file exists, and names a class once. */
    @Test
    public void theTablesFilesExistAndEachIsOneTasks() {
        java.util.Set<String> seen = new java.util.HashSet<>();
        for (Task task : TaskTable.standard().all()) {
            for (String file : task.projectFiles()) {
                assertTrue(file, Files.isRegularFile(Path.of(file)));
                assertTrue(file + " is in two tasks", seen.add(file));
            }
        }
    }

    private static void refused(String text, Map<String, String> overrides, String message) {
        try {
            read(text, overrides);
            fail("accepted: " + text);
        } catch (AssignmentException e) {
            assertEquals(message, e.getMessage());
        }
    }

    private static void tableRefused(String text, String message) {
        try {
            TaskTable.parse(new StringReader(text), "tasks.properties");
            fail("accepted: " + text);
        } catch (AssignmentException | IOException e) {
            assertEquals(message, e.getMessage());
        }
    }
}
