package ray.assignment;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.stream.Collectors;

/**
 * The table of tasks (ray/assignment/tasks.properties): the one place that says which tasks exist,
 * their titles, student files, test classes, scenes, and what each builds on. An {@link Assignment}
 * picks from it.
 */
public final class TaskTable {
    /** The table's resource, and its path in the project. */
    public static final String RESOURCE = "ray/assignment/tasks.properties";
    public static final String PROJECT_FILE = "src/main/resources/" + RESOURCE;

    private static final TaskTable STANDARD = load();

    private final Map<String, Task> tasks;

    TaskTable(List<Task> tasks) {
        Map<String, Task> byId = new LinkedHashMap<>();
        for (Task task : tasks) {
            byId.put(task.id(), task);
        }
        this.tasks = byId;
    }

    /** The table this build ships. */
    public static TaskTable standard() {
        return STANDARD;
    }

    /** Every task, in the table's order. */
    public List<Task> all() {
        return List.copyOf(tasks.values());
    }

    /** Every task's id, in the table's order. */
    public List<String> ids() {
        return List.copyOf(tasks.keySet());
    }

    /** The task with this id, or empty. */
    public Optional<Task> find(String id) {
        return Optional.ofNullable(tasks.get(id));
    }

    /** The task with this id; an unknown id is an error that names the known ones. */
    public Task get(String id) {
        Task task = tasks.get(id);
        if (task == null) {
            throw new AssignmentException("there is no task \"" + id + "\"; the tasks are " + String.join(", ", ids()));
        }
        return task;
    }

    /** The task whose test patterns match {@code className}, or empty. */
    public Optional<Task> ofTestClass(String className) {
        return tasks.values().stream().filter(t -> t.hasTestClass(className)).findFirst();
    }

    /** The task one of whose files is the class {@code simpleName} ("Sphere"), or empty. */
    public Optional<Task> ofStudentClass(String simpleName) {
        return tasks.values().stream().filter(t -> t.classNames().contains(simpleName)).findFirst();
    }

    /** The task one of whose files is {@code projectFile} ("src/main/java/ray/surface/Sphere.java"), or empty. */
    public Optional<Task> ofFile(String projectFile) {
        String normalized = projectFile.replace('\\', '/');
        return tasks.values().stream().filter(t -> t.projectFiles().contains(normalized)).findFirst();
    }

    private static TaskTable load() {
        try (InputStream in = TaskTable.class.getClassLoader().getResourceAsStream(RESOURCE)) {
            if (in == null) {
                throw new AssignmentException(PROJECT_FILE + " is missing from the build: restore it from the handout");
            }
            return parse(new InputStreamReader(in, StandardCharsets.UTF_8), PROJECT_FILE);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Reads a table in the form of tasks.properties; {@code name} is how errors name the file. */
    static TaskTable parse(Reader reader, String name) throws IOException {
        Properties p = new Properties();
        p.load(reader);
        List<String> ids = list(p.getProperty("tasks"));
        if (ids.isEmpty()) {
            throw new AssignmentException(name + ": no `tasks = id, id, …` line");
        }
        List<Task> tasks = new ArrayList<>();
        for (String id : ids) {
            String title = required(p, name, id + ".title");
            List<String> files = list(required(p, name, id + ".files"));
            List<String> tests = list(required(p, name, id + ".tests"));
            List<String> needs = list(p.getProperty(id + ".needs"));
            for (String need : needs) {
                if (!ids.contains(need)) {
                    throw new AssignmentException(name + ": " + id + ".needs names \"" + need + "\", which is no task of the table");
                }
            }
            String extra = p.getProperty(id + ".extraCredit", "false").trim();
            if (!extra.equals("true") && !extra.equals("false")) {
                throw new AssignmentException(name + ": " + id + ".extraCredit is \"" + extra + "\"; expected true or false");
            }
            double points = positiveOrZero(p.getProperty(id + ".points", "0"), name + ": " + id + ".points");
            String course = p.getProperty(id + ".course");
            if (course != null && !Assignment.COURSES.contains(course.trim())) {
                throw new AssignmentException(name + ": " + id + ".course is \"" + course.trim() + "\"; expected one of "
                        + String.join(", ", new java.util.TreeSet<>(Assignment.COURSES)) + ", or no such line for a task of every course");
            }
            tasks.add(new Task(id, title, files, tests, list(p.getProperty(id + ".scenes")), points, Boolean.parseBoolean(extra), needs,
                    course == null ? null : course.trim()));
        }
        for (String key : p.stringPropertyNames()) {
            String owner = key.contains(".") ? key.substring(0, key.indexOf('.')) : null;
            if (!key.equals("tasks") && (owner == null || !ids.contains(owner))) {
                throw new AssignmentException(name + ": " + key + " belongs to no task of the `tasks` line");
            }
        }
        return new TaskTable(tasks);
    }

    /** A number of points: finite and not negative; {@code what} names the file and key in the error. */
    static double positiveOrZero(String value, String what) {
        try {
            double x = Double.parseDouble(value.trim());
            if (Double.isFinite(x) && x >= 0) {
                return x;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new AssignmentException(what + " is \"" + value.trim() + "\"; expected a number of points, 0 or more");
    }

    private static String required(Properties p, String name, String key) {
        String value = p.getProperty(key);
        if (value == null || value.isBlank()) {
            throw new AssignmentException(name + ": " + key + " is missing");
        }
        return value.trim();
    }

    /** "a, b, c" → [a, b, c]; blank or null → []. */
    static List<String> list(String value) {
        if (value == null || value.isBlank()) {
            return List.of();
        }
        return Arrays.stream(value.split(",")).map(String::trim).filter(s -> !s.isEmpty()).collect(Collectors.toList());
    }
}
