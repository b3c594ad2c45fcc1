package ray.assignment;

import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * One entry of the table of tasks ({@link TaskTable}): a part of the renderer that an assignment may
 * give students to write.
 *
 * @param id          the stable id, as assignment files and {@code -Ptask} name it ("sphere")
 * @param title       how messages name it: "Sphere" in "Task 2 (Sphere)"
 * @param files       the files students fill in, relative to src/main/java ("ray/surface/Sphere.java")
 * @param tests       its test classes as Gradle's test filter reads them, '*' standing for any characters
 * @param scenes      the scenes (file names without .xml) whose render tests count toward it
 * @param extraCredit whether its tests are extra credit where the assignment does not say
 * @param needs       the ids of the tasks it builds on
 */
public record Task(String id, String title, List<String> files, List<String> tests, List<String> scenes, boolean extraCredit,
        List<String> needs) {

    public Task {
        files = List.copyOf(files);
        tests = List.copyOf(tests);
        scenes = List.copyOf(scenes);
        needs = List.copyOf(needs);
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
}
