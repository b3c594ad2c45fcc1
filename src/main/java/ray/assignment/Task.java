package ray.assignment;

import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * One entry of the table of tasks ({@link TaskTable}): a part of the renderer that an assignment may
 * give students to write. (A class, not a record: Debian's Gradle 4.4 cannot read a record's class
 * file on the students' compile classpath.)
 */
public final class Task {
    private final String id;
    private final String title;
    private final List<String> files;
    private final List<String> tests;
    private final List<String> scenes;
    private final double points;
    private final boolean extraCredit;
    private final List<String> needs;
    private final String course;

    /**
     * @param id          the stable id, as assignment files and {@code -Ptask} name it ("sphere")
     * @param title       how messages name it: "Sphere" in "Task 2 (Sphere)"
     * @param files       the files students fill in, relative to src/main/java ("ray/surface/Sphere.java")
     * @param tests       its test classes as Gradle's test filter reads them, '*' standing for any characters
     * @param scenes      the scenes (file names without .xml) whose render tests count toward it
     * @param points      what it is worth: its regular tests' points together (an extra-credit task's,
     *                    its tests' bonus points), which the grader shares among its tests in
     *                    proportion to their {@code @Points}; 0 leaves the tests' own points as they are
     * @param extraCredit whether its tests are extra credit where the assignment does not say
     * @param needs       the ids of the tasks it builds on
     * @param course      the course conventions it belongs to ("2019" for the BRDFs), or null for a task of every course
     */
    public Task(String id, String title, List<String> files, List<String> tests, List<String> scenes, double points, boolean extraCredit,
            List<String> needs, String course) {
        this.id = id;
        this.title = title;
        this.files = List.copyOf(files);
        this.tests = List.copyOf(tests);
        this.scenes = List.copyOf(scenes);
        this.points = points;
        this.extraCredit = extraCredit;
        this.needs = List.copyOf(needs);
        this.course = course;
    }

    /**
     * The course whose conventions the task belongs to ("2017": the light loops, "2019": the BRDFs),
     * or null when it is the same under every course (the geometry, the cameras). An assignment of
     * another course cannot choose it, and its scenes are that course's (scenes-2019/ for 2019).
     */
    public String course() {
        return course;
    }

    public String id() {
        return id;
    }

    public String title() {
        return title;
    }

    /** The files students fill in, relative to src/main/java. */
    public List<String> files() {
        return files;
    }

    /** Its test classes, as Gradle's test filter patterns. */
    public List<String> tests() {
        return tests;
    }

    /** The scenes whose render tests count toward it. */
    public List<String> scenes() {
        return scenes;
    }

    /** What it is worth by default (see the constructor); an assignment may say otherwise. */
    public double points() {
        return points;
    }

    /** Whether it is extra credit by default. */
    public boolean extraCredit() {
        return extraCredit;
    }

    /** The ids of the tasks it builds on. */
    public List<String> needs() {
        return needs;
    }

    /** The files as the project names them: "src/main/java/ray/surface/Sphere.java". */
    public List<String> projectFiles() {
        return files.stream().map(f -> "src/main/java/" + f).collect(Collectors.toList());
    }

    /** The classes students fill in, by simple name ("PerspectiveCamera"), in the order of {@link #files}. */
    public List<String> classNames() {
        return files.stream().map(f -> f.substring(f.lastIndexOf('/') + 1, f.length() - ".java".length())).collect(Collectors.toList());
    }

    /** Whether {@code className} (binary name, "ray.surface.SphereTest") is one of this task's test classes. */
    public boolean hasTestClass(String className) {
        return tests.stream().anyMatch(pattern -> matches(pattern, className));
    }

    /** Gradle's test filter on a class name: '*' stands for any characters, everything else for itself. */
    static boolean matches(String pattern, String className) {
        String regex = Stream.of(pattern.split("\\*", -1)).map(Pattern::quote).collect(Collectors.joining(".*"));
        return className.matches(regex);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Task t && t.id.equals(id) && t.title.equals(title) && t.files.equals(files) && t.tests.equals(tests)
                && t.scenes.equals(scenes) && t.points == points && t.extraCredit == extraCredit && t.needs.equals(needs);
    }

    @Override
    public int hashCode() {
        return id.hashCode();
    }

    @Override
    public String toString() {
        return id;
    }
}
