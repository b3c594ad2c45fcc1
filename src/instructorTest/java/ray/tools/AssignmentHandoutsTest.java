package ray.tools;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;
import ray.assignment.Assignment;
import ray.assignment.Task;
import ray.grading.CompileResult;
import ray.grading.ProjectCompiler;
import ray.grading.SolutionMarkers;
import ray.grading.TestOutcome;
import ray.grading.TestProcess;

/**
 * The handout of each assignment: every preset, and assignments of a few tasks in an order of their
 * own. A chosen task's files ship as stubs whose TODO comments carry the assignment's number for it;
 * a task left out ships solved, without a TODO, and without its tests. On the stubs exactly the
 * chosen tasks' tests fail, each under its assignment number; with the solution every test passes.
 */
@RunWith(Parameterized.class)
public class AssignmentHandoutsTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static final Path PROJECT = Path.of(".");
    /** The libraries only: a handout must compile without any instructor class on the classpath. */
    private static final String LIBRARIES = Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
            .filter(p -> p.endsWith(".jar")).collect(Collectors.joining(File.pathSeparator));
    private static final Pattern TODO = Pattern.compile("TODO\\(Task (\\d+)\\)");

    private final String name;
    private final Assignment assignment;

    public AssignmentHandoutsTest(String name, String given, String tasks, String hints) throws Exception {
        this.name = name;
        this.assignment = Assignment.resolve(PROJECT, given, Assignment.overrides(tasks, hints));
    }

    /** Every preset at every hint level, and assignments of a few tasks in orders of their own. */
    @Parameters(name = "{0}")
    public static List<Object[]> assignments() {
        List<Object[]> all = new java.util.ArrayList<>();
        for (String preset : Assignment.presetNames()) {
            for (ray.assignment.HintLevel level : ray.assignment.HintLevel.values()) {
                all.add(new Object[] {preset + "-" + level.id(), preset, null, level.id()});
            }
        }
        // Two tasks, in an order of their own: the group is Task 1, the sphere Task 2; the rest ships solved.
        all.add(new Object[] {"group-then-sphere", "intersections", "group, sphere", null});
        // The extra credit chosen with one required task: Task 2 (Cylinder) stays extra credit.
        all.add(new Object[] {"textures-and-cylinder", "intersections", "textures, cylinder", "steps"});
        return all;
    }

    @Test(timeout = 600_000)
    public void chosenTasksShipAsNumberedStubsTheRestSolvedAndOnlyTheirTestsFail() throws Exception {
        Path handout = FOLDER.getRoot().toPath().resolve(name);
        List<String> files = Handout.build(PROJECT, handout, assignment);

        // The handout's own assignment file reads back as this assignment.
        String shipped = Files.readString(handout.resolve("src/main/resources/" + Assignment.RESOURCE), StandardCharsets.UTF_8);
        assertEquals(shipped, assignment, Assignment.resolve(handout, "src/main/resources/" + Assignment.RESOURCE, Map.of()));
        assertFalse("the instructor's assignment file ships", files.contains(Assignment.PROJECT_FILE));

        for (Task task : assignment.table().all()) {
            int number = assignment.number(task.id());
            for (String file : task.projectFiles()) {
                String source = Files.readString(PROJECT.resolve(file), StandardCharsets.UTF_8);
                String text = Files.readString(handout.resolve(file), StandardCharsets.UTF_8);
                Set<String> todos = new TreeSet<>();
                Matcher m = TODO.matcher(text);
                while (m.find()) {
                    todos.add(m.group(1));
                }
                if (number > 0) {
                    assertEquals(file + " is a stub", SolutionMarkers.studentVersion(source, file, number, assignment.hints(task.id())), text);
                    checkHints(file, source, text, assignment.hints(task.id()));
                    assertEquals(file + "'s TODO comments carry its task's number", Set.of(String.valueOf(number)), todos);
                } else {
                    assertEquals(file + " ships solved", SolutionMarkers.solvedVersion(source, file), text);
                    assertEquals(file + " ships solved, without a TODO: " + todos, Set.of(), todos);
                    assertFalse(file + " ships solved, without a stub line", text.contains(SolutionMarkers.STUB.strip()));
                }
            }
        }
        for (String file : files) {
            if (file.startsWith("src/test/java/") && file.endsWith("Test.java")) {
                String className = file.substring("src/test/java/".length(), file.length() - ".java".length()).replace('/', '.');
                assignment.table().ofTestClass(className).ifPresent(t -> assertTrue(file + " is a test of " + t.id()
                        + ", which this assignment leaves out", assignment.isChosen(t.id())));
            }
        }

        checkDocs(handout);

        List<TestOutcome> onStubs = compileAndRun(handout, "stubs");
        Set<Integer> failing = onStubs.stream().filter(t -> t.task() > 0).map(TestOutcome::task).collect(Collectors.toCollection(TreeSet::new));
        Set<Integer> chosen = assignment.tasks().stream().map(t -> assignment.number(t.id())).collect(Collectors.toCollection(TreeSet::new));
        assertEquals("the tasks whose graded tests the handout holds", chosen, failing);
        for (TestOutcome t : onStubs) {
            assertTrue(t.id() + " judges no task of this assignment", t.task() > 0);
            assertFalse(t.id() + " passes on the stubs", t.passed());
            String title = assignment.task(t.task()).orElseThrow().title();
            assertEquals(t.id(), title, t.taskTitle());
            assertTrue(t.id() + "'s failure does not point to its TODO: " + t.message(), t.message().contains("TODO(Task " + t.task() + ")"));
        }

        Path solved = FOLDER.getRoot().toPath().resolve(name + "-solved");
        Handout.build(PROJECT, solved, assignment);
        for (Task task : assignment.tasks()) {
            for (String file : task.projectFiles()) {
                Files.copy(PROJECT.resolve(file), solved.resolve(file), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            }
        }
        List<TestOutcome> withSolution = compileAndRun(solved, "solved");
        assertEquals(onStubs.size(), withSolution.size());
        for (TestOutcome t : withSolution) {
            assertTrue(t.id() + " fails with the solution in place: " + t.message(), t.passed());
        }
    }

    /** Named methods, which the goal level leaves to the student (the course's own TODOs named none). */
    private static final List<String> ALGORITHMS = List.of("Cramer", "Möller", "Trumbore", "discriminant", "quadratic formula", "Shirley");

    /**
     * A TODO at its level: every level keeps the goal and every convention line; the goal's own lines
     * hold no formula (no '=' or '·', no named method); the steps are words, without formulas; the
     * formulas are today's text.
     */
    private static void checkHints(String file, String source, String shipped, ray.assignment.HintLevel level) {
        List<List<String>> todos = todoComments(shipped);
        List<List<String>> sourceTodos = todoComments(source);
        assertEquals(file + "'s TODO comments", sourceTodos.size(), todos.size());
        for (int k = 0; k < todos.size(); k++) {
            checkHints(file, sourceTodos.get(k), todos.get(k), level);
        }
    }

    /** One TODO comment (a file may hold several, one per method) at its level, against its source. */
    private static void checkHints(String file, List<String> sourceTodo, List<String> todo, ray.assignment.HintLevel level) {
        int conventions = indexOfConventions(sourceTodo);
        assertTrue(file + "'s TODO has no conventions", conventions > 0);
        int hintsAt = sourceTodo.stream().filter(l -> l.startsWith("HINTS ")).findFirst().map(sourceTodo::indexOf).orElse(-1);
        assertTrue(file + "'s TODO has no hints", hintsAt > conventions);
        for (String convention : sourceTodo.subList(conventions, hintsAt)) {
            assertTrue(file + " at " + level.id() + " lacks the convention line: " + convention, todo.contains(convention));
        }
        List<String> goal = todo.subList(1, indexOfConventions(todo));
        for (String line : goal) {
            assertFalse(file + "'s goal states a formula: " + line, line.contains("=") || line.contains("·"));
            for (String algorithm : ALGORITHMS) {
                assertFalse(file + "'s goal names a method: " + line, line.contains(algorithm));
            }
        }
        List<String> hints = todo.subList(todo.indexOf(sourceTodo.get(hintsAt - 1)) + 1, todo.size());
        List<String> expected = block(sourceTodo, "HINTS " + level.id());
        assertEquals(file + "'s hints at " + level.id(), expected, hints);
        if (level == ray.assignment.HintLevel.STEPS) {
            assertFalse(file + " at steps gives no steps", hints.isEmpty());
            for (String line : hints) {
                assertFalse(file + "'s steps state a formula: " + line, line.contains("=") || line.contains("·"));
            }
        }
    }

    /** The lines of the source TODO's hints block that begins with {@code marker} (none for the goal, which has no block). */
    private static List<String> block(List<String> sourceTodo, String marker) {
        int begin = sourceTodo.indexOf(marker);
        if (begin < 0) {
            return List.of();
        }
        int end = begin + 1;
        while (end < sourceTodo.size() && !sourceTodo.get(end).startsWith("HINTS ") && !sourceTodo.get(end).equals("END HINTS")) {
            end++;
        }
        return sourceTodo.subList(begin + 1, end);
    }

    /** Each TODO comment's lines, without the comment's slashes and indentation, in file order. */
    private static List<List<String>> todoComments(String text) {
        List<List<String>> comments = new java.util.ArrayList<>();
        List<String> lines = null;
        for (String line : text.split("\n")) {
            String t = line.strip();
            if (t.startsWith("// TODO(Task")) {
                lines = new java.util.ArrayList<>();
                comments.add(lines);
            } else if (!t.startsWith("//") || t.equals(SolutionMarkers.BEGIN)) {
                lines = null;
            }
            if (lines != null) {
                lines.add(t.replaceFirst("^//\\s?", "").strip());
            }
        }
        return comments;
    }

    private static int indexOfConventions(List<String> todo) {
        for (int i = 0; i < todo.size(); i++) {
            if (todo.get(i).startsWith("Conventions")) {
                return i;
            }
        }
        return -1;
    }

    /**
     * The students' docs speak of this assignment: every task number they name is one of its tasks,
     * no marker is left, README.md's table and grading.md's table of scenes hold exactly its tasks
     * in its order, and each task's section of assignment.md is there under its number.
     */
    private void checkDocs(Path handout) throws Exception {
        Pattern named = Pattern.compile("\\bTasks? (\\d+)|TODO\\(Task (\\d+)\\)|-Ptask=(\\d+)");
        for (String doc : List.of("README.md", "docs/assignment.md", "docs/grading.md", "docs/architecture.md", "docs/cli.md")) {
            String text = Files.readString(handout.resolve(doc), StandardCharsets.UTF_8);
            assertFalse(doc + " keeps a task marker", text.contains("<!-- task:") || text.contains("<!-- TASK") || text.contains("<!-- IF"));
            Matcher m = named.matcher(text);
            while (m.find()) {
                String number = m.group(1) != null ? m.group(1) : m.group(2) != null ? m.group(2) : m.group(3);
                assertTrue(doc + " names " + m.group() + ", which this assignment does not have",
                        assignment.task(Integer.parseInt(number)).isPresent());
            }
        }
        List<String> expectedRows = new java.util.ArrayList<>();
        List<String> expectedHeadings = new java.util.ArrayList<>();
        for (Task task : assignment.tasks()) {
            if (!task.scenes().isEmpty()) {
                expectedRows.add("Task " + assignment.number(task.id()) + " " + String.join(", ", task.scenes()));
            }
            expectedHeadings.add("## Task " + assignment.number(task.id()));
        }
        List<String> rows = Files.readAllLines(handout.resolve("docs/grading.md"), StandardCharsets.UTF_8).stream()
                .filter(line -> line.startsWith("| Task "))
                .map(line -> line.replaceAll("^\\| (Task \\d+) \\([^)]*\\) \\| ([^|(]*?)\\s*(\\(.*)?\\|\\s*$", "$1 $2"))
                .collect(Collectors.toList());
        assertEquals("docs/grading.md's table of scenes", expectedRows, rows);
        List<String> headings = Files.readAllLines(handout.resolve("docs/assignment.md"), StandardCharsets.UTF_8).stream()
                .filter(line -> line.startsWith("## Task ")).map(line -> line.replaceAll("^(## Task \\d+).*", "$1"))
                .collect(Collectors.toList());
        assertEquals("docs/assignment.md's task sections", expectedHeadings, headings);
        // docs/assignment.md gives the math its level includes: the sphere's roots only at formulas,
        // its texture coordinates (a convention) at every level.
        if (assignment.isChosen("sphere")) {
            String doc = Files.readString(handout.resolve("docs/assignment.md"), StandardCharsets.UTF_8);
            assertEquals("the sphere's roots in docs/assignment.md at " + assignment.hints("sphere").id(),
                    assignment.hints("sphere") == ray.assignment.HintLevel.FORMULAS, doc.contains("t = (−b ± √Δ)/(2a)"));
            assertTrue(doc.contains("u = ½ + atan2(x, z)/(2π),    v = ½ + asin(y)/π"));
        }
        long readmeRows = Files.readAllLines(handout.resolve("README.md"), StandardCharsets.UTF_8).stream()
                .filter(line -> line.startsWith("| Task ")).count();
        assertEquals("README.md's table of tasks", assignment.tasks().size(), readmeRows);
    }

    private static List<TestOutcome> compileAndRun(Path tree, String what) throws Exception {
        CompileResult compiled = ProjectCompiler.compile(tree, tree.resolve("classes"), LIBRARIES);
        assertTrue("the " + what + " handout does not compile on its own:\n" + compiled.messages(), compiled.ok());
        return new TestProcess(tree, tree.resolve("classes"), LIBRARIES, tree.resolve("test-run")).withUngradedTests().run(null);
    }
}
