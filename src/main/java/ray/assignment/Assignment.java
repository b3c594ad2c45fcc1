package ray.assignment;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.StringReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.Set;
import java.util.TreeSet;

/**
 * What students write: the tasks an instructor chose from the {@link TaskTable}, in order (their
 * numbers are their places, from 1), which of them are extra credit, and the course's conventions.
 * A task of the table that is not chosen ships solved: its solution stays, its tests are not the
 * student's.
 *
 * <p>Written as an assignment file (properties): {@code preset = NAME} starts from a ready-made one
 * (ray/assignment/presets/NAME.properties), and {@code tasks}, {@code extraCredit}, {@code hints}
 * (and a task's own {@code hints.ID}) and {@code course} say or override the rest. The build carries the project's assignment.properties into the
 * classpath ({@link #RESOURCE}), where {@link #current()} reads it; without one, the assignment is
 * the preset {@value #DEFAULT_PRESET}.
 */
public final class Assignment {
    public static final String RESOURCE = "ray/assignment/assignment.properties";
    /** The instructor's assignment file, at the project's root. */
    public static final String PROJECT_FILE = "assignment.properties";
    public static final String DEFAULT_PRESET = "intersections";
    /** The course conventions ray1 renders with. */
    public static final Set<String> COURSES = Set.of("2017", "2019");
    private static final List<String> KEYS = List.of("preset", "tasks", "extraCredit", "hints", "course");
    /** A task's own hint level: {@code hints.ID = LEVEL}. */
    private static final String TASK_HINTS = "hints.";
    /** A task's points in this assignment: {@code points.ID = N}. */
    private static final String TASK_POINTS = "points.";
    private static final String PRESETS = "ray/assignment/presets/";

    private static volatile Assignment current;

    private final TaskTable table;
    private final List<Task> tasks;
    private final Set<String> extraCredit;
    private final HintLevel hints;
    /** The tasks whose hint level is not {@link #hints}. */
    private final Map<String, HintLevel> taskHints;
    /** The tasks whose points are not the table's. */
    private final Map<String, Double> taskPoints;
    private final String course;

    private Assignment(TaskTable table, List<Task> tasks, Set<String> extraCredit, HintLevel hints, Map<String, HintLevel> taskHints,
            Map<String, Double> taskPoints, String course) {
        this.table = table;
        this.tasks = List.copyOf(tasks);
        this.extraCredit = Set.copyOf(extraCredit);
        this.hints = hints;
        this.taskHints = Map.copyOf(taskHints);
        this.taskPoints = Map.copyOf(taskPoints);
        this.course = course;
    }

    /**
     * Makes {@code assignment} this process's {@link #current()}: the grader's and the instructor's
     * tools grade or build the assignment they were asked for, whatever the class path holds.
     */
    public static void use(Assignment assignment) {
        current = java.util.Objects.requireNonNull(assignment);
    }

    /** The assignment this build was made for (see the class comment), or the one {@link #use} set. */
    public static Assignment current() {
        Assignment a = current;
        if (a == null) {
            try (InputStream in = Assignment.class.getClassLoader().getResourceAsStream(RESOURCE)) {
                a = in == null ? preset(DEFAULT_PRESET)
                        : read(new InputStreamReader(in, StandardCharsets.UTF_8), PROJECT_FILE, TaskTable.standard(), Map.of());
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            current = a;
        }
        return a;
    }

    /** A ready-made assignment by name ("intersections", "course-2017", "course-2018", "course-2019", "course-2019-part2"). */
    public static Assignment preset(String name) {
        return preset(name, Map.of());
    }

    /** A ready-made assignment with keys given for one run. */
    private static Assignment preset(String name, Map<String, String> overrides) {
        return read(new StringReader(presetText(name)), name, TaskTable.standard(), overrides);
    }

    /** The names of the ready-made assignments. */
    public static List<String> presetNames() {
        return List.of("intersections", "course-2017", "course-2018", "course-2019", "course-2019-part2");
    }

    /**
     * The assignment an instructor's build asks for: {@code given} is a preset's name or an assignment
     * file (-Passignment), or null for the project's own assignment.properties (else the default
     * preset); {@code overrides} holds keys given for this run alone (-Ptasks as "tasks").
     */
    public static Assignment resolve(Path project, String given, Map<String, String> overrides) throws IOException {
        if (given != null && presetNames().contains(given)) {
            return preset(given, overrides);
        }
        Path file = given != null ? project.resolve(given) : project.resolve(PROJECT_FILE);
        if (given != null && !Files.isRegularFile(file)) {
            throw new AssignmentException("-Passignment=" + given + ": no such preset or file; the presets are "
                    + String.join(", ", presetNames()));
        }
        if (!Files.isRegularFile(file)) {
            return preset(DEFAULT_PRESET, overrides);
        }
        try (Reader reader = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            return read(reader, given != null ? given : PROJECT_FILE, TaskTable.standard(), overrides);
        }
    }

    /** The keys given for one run: {@code tasks} and {@code hints}, each when not null. */
    public static Map<String, String> overrides(String tasks, String hints) {
        Map<String, String> overrides = new java.util.LinkedHashMap<>();
        if (tasks != null) {
            overrides.put("tasks", tasks);
        }
        if (hints != null) {
            overrides.put("hints", hints);
        }
        return overrides;
    }

    /** Reads an assignment file; {@code name} is how errors name it. */
    static Assignment read(Reader reader, String name, TaskTable table, Map<String, String> overrides) throws UncheckedIOException {
        Properties file = new Properties();
        try {
            file.load(reader);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        for (String key : file.stringPropertyNames()) {
            if (!KEYS.contains(key) && !key.startsWith(TASK_HINTS) && !key.startsWith(TASK_POINTS)) {
                throw new AssignmentException(name + ": unknown key \"" + key + "\"; expected " + String.join(", ", KEYS)
                        + ", hints.ID or points.ID");
            }
        }
        Properties p = new Properties();
        String preset = file.getProperty("preset");
        if (preset != null) {
            preset = preset.trim();
            if (!presetNames().contains(preset)) {
                throw new AssignmentException(name + ": preset = " + preset + " is no preset; the presets are " + String.join(", ", presetNames()));
            }
            try {
                p.load(new StringReader(presetText(preset)));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        for (String key : file.stringPropertyNames()) {
            p.setProperty(key, file.getProperty(key));
        }
        overrides.forEach(p::setProperty);
        String where = overrides.isEmpty() ? name : name + " with " + String.join(" and ", overrides.keySet()) + " given";

        List<String> ids = TaskTable.list(p.getProperty("tasks"));
        if (ids.isEmpty()) {
            throw new AssignmentException(where + ": no tasks; give `tasks = id, id, …` from " + String.join(", ", table.ids()));
        }
        List<Task> tasks = new ArrayList<>();
        Set<String> seen = new LinkedHashSet<>();
        for (String id : ids) {
            if (table.find(id).isEmpty()) {
                throw new AssignmentException(where + ": there is no task \"" + id + "\"; the tasks are " + String.join(", ", table.ids()));
            }
            if (!seen.add(id)) {
                throw new AssignmentException(where + ": the task " + id + " is chosen twice");
            }
            tasks.add(table.get(id));
        }
        for (Task task : tasks) {
            for (String need : task.needs()) {
                if (!seen.contains(need)) {
                    throw new AssignmentException(where + ": the task " + task.id() + " builds on " + need + ", which is not chosen; choose both or neither");
                }
            }
        }
        Set<String> extra = new TreeSet<>();
        if (p.getProperty("extraCredit") != null) {
            for (String id : TaskTable.list(p.getProperty("extraCredit"))) {
                if (table.find(id).isEmpty()) {
                    throw new AssignmentException(where + ": extraCredit names \"" + id + "\", which is no task; the tasks are " + String.join(", ", table.ids()));
                }
                if (seen.contains(id)) {
                    extra.add(id);
                }
            }
        } else {
            tasks.stream().filter(Task::extraCredit).forEach(t -> extra.add(t.id()));
        }
        if (extra.size() == tasks.size()) {
            throw new AssignmentException(where + ": every chosen task is extra credit; at least one must be required");
        }
        HintLevel hints = level(p.getProperty("hints", HintLevel.FORMULAS.id()), where, "hints");
        Map<String, HintLevel> taskHints = new java.util.TreeMap<>();
        for (String key : p.stringPropertyNames()) {
            if (key.startsWith(TASK_HINTS)) {
                String id = key.substring(TASK_HINTS.length());
                if (table.find(id).isEmpty()) {
                    throw new AssignmentException(where + ": " + key + " names no task; the tasks are " + String.join(", ", table.ids()));
                }
                HintLevel level = level(p.getProperty(key), where, key);
                if (level != hints && seen.contains(id)) {
                    taskHints.put(id, level);
                }
            }
        }
        Map<String, Double> taskPoints = new java.util.TreeMap<>();
        for (String key : p.stringPropertyNames()) {
            if (key.startsWith(TASK_POINTS)) {
                String id = key.substring(TASK_POINTS.length());
                if (table.find(id).isEmpty()) {
                    throw new AssignmentException(where + ": " + key + " names no task; the tasks are " + String.join(", ", table.ids()));
                }
                double points = TaskTable.positiveOrZero(p.getProperty(key), where + ": " + key);
                if (points != table.get(id).points() && seen.contains(id)) {
                    taskPoints.put(id, points);
                }
            }
        }
        String course = p.getProperty("course", "2017").trim();
        if (!COURSES.contains(course)) {
            throw new AssignmentException(where + ": course = " + course + "; ray1 renders with the course's conventions of " + String.join(", ", new TreeSet<>(COURSES)));
        }
        for (Task task : tasks) {
            if (task.course() != null && !task.course().equals(course)) {
                throw new AssignmentException(where + ": the task " + task.id() + " is written by the course's " + task.course()
                        + " conventions, and this assignment's course is " + course + "; choose it with course = " + task.course());
            }
        }
        return new Assignment(table, tasks, extra, hints, taskHints, taskPoints, course);
    }

    private static HintLevel level(String value, String where, String key) {
        HintLevel level = HintLevel.of(value);
        if (level == null) {
            throw new AssignmentException(where + ": " + key + " = " + value.trim() + "; expected goal, steps or formulas");
        }
        return level;
    }

    private static String presetText(String name) {
        try (InputStream in = Assignment.class.getClassLoader().getResourceAsStream(PRESETS + name + ".properties")) {
            if (in == null) {
                throw new AssignmentException("there is no preset \"" + name + "\"; the presets are " + String.join(", ", presetNames()));
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The table the tasks come from. */
    public TaskTable table() {
        return table;
    }

    /** The chosen tasks, in order: task {@code n} is {@code tasks().get(n - 1)}. */
    public List<Task> tasks() {
        return tasks;
    }

    public String course() {
        return course;
    }

    /**
     * What task {@code id} is worth in this assignment: its regular tests' points together (an
     * extra-credit task's, its bonus points), or 0 to keep its tests' own points.
     */
    public double points(String id) {
        return taskPoints.getOrDefault(id, table.get(id).points());
    }

    /** How much the TODO comments and failure messages of task {@code id} say. */
    public HintLevel hints(String id) {
        return taskHints.getOrDefault(id, hints);
    }

    public boolean isChosen(String id) {
        return tasks.stream().anyMatch(t -> t.id().equals(id));
    }

    /** The task's number in this assignment (from 1), or 0 when it is not chosen (it ships solved). */
    public int number(String id) {
        for (int i = 0; i < tasks.size(); i++) {
            if (tasks.get(i).id().equals(id)) {
                return i + 1;
            }
        }
        return 0;
    }

    public boolean isExtraCredit(String id) {
        return extraCredit.contains(id);
    }

    /** Task {@code number}, or empty. */
    public Optional<Task> task(int number) {
        return number >= 1 && number <= tasks.size() ? Optional.of(tasks.get(number - 1)) : Optional.empty();
    }

    /** The chosen task a student names by number ("2") or id ("sphere"), or empty. */
    public Optional<Task> named(String numberOrId) {
        String s = numberOrId.trim();
        if (s.matches("\\d{1,3}")) {
            return task(Integer.parseInt(s));
        }
        return isChosen(s) ? Optional.of(table.get(s)) : Optional.empty();
    }

    /** "Task 2 (Sphere)"; a task not chosen is named by its title alone. */
    public String label(String id) {
        int n = number(id);
        return n == 0 ? table.get(id).title() : "Task " + n + " (" + table.get(id).title() + ")";
    }

    /** "TODO(Task 2)", the comment that marks where a task's code goes. */
    public String todo(String id) {
        return "TODO(Task " + number(id) + ")";
    }

    /** The student file's task: the chosen task one of whose files it is, or empty (a framework file). */
    public Optional<Task> ofFile(String projectFile) {
        return table.ofFile(projectFile).filter(t -> isChosen(t.id()));
    }

    /** The assignment as a complete file (no preset), which reads back as this assignment. */
    public String toFileText(String comment) {
        StringBuilder out = new StringBuilder();
        for (String line : comment.split("\n")) {
            out.append("# ").append(line).append('\n');
        }
        out.append("tasks = ").append(String.join(", ", tasks.stream().map(Task::id).toArray(String[]::new))).append('\n');
        out.append("extraCredit = ").append(String.join(", ", extraCredit)).append('\n');
        out.append("hints = ").append(hints.id()).append('\n');
        taskHints.forEach((id, level) -> out.append("hints.").append(id).append(" = ").append(level.id()).append('\n'));
        taskPoints.forEach((id, points) -> out.append("points.").append(id).append(" = ").append(points).append('\n'));
        out.append("course = ").append(course).append('\n');
        return out.toString();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Assignment a && a.tasks.equals(tasks) && a.extraCredit.equals(extraCredit) && a.hints == hints
                && a.taskHints.equals(taskHints) && a.taskPoints.equals(taskPoints) && a.course.equals(course);
    }

    @Override
    public int hashCode() {
        return tasks.hashCode() * 31 + extraCredit.hashCode();
    }

    @Override
    public String toString() {
        return toFileText("").strip();
    }
}
