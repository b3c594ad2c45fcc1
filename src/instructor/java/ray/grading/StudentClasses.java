package ray.grading;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collection;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * What a student file may define: its public class and the classes nested in it (local and
 * anonymous classes too), nothing else. A second top-level class could take the name of a class the
 * framework or a test has; it is refused, with a line naming it, before anything runs.
 */
final class StudentClasses {
    private StudentClasses() {
    }

    /**
     * Why the classes compiled from {@code files} (paths as src/main/java/ray/surface/Sphere.java) into
     * {@code classes} are refused, or null when each is its file's own class or nested in it.
     */
    static String refused(Path classes, Collection<String> files) throws IOException {
        Set<String> own = new TreeSet<>();
        for (String file : files) {
            own.add(file.substring("src/main/java/".length(), file.length() - ".java".length()));
        }
        List<String> compiled;
        try (Stream<Path> walk = Files.walk(classes)) {
            compiled = walk.filter(Files::isRegularFile).map(p -> classes.relativize(p).toString().replace(File.separatorChar, '/'))
                    .sorted().collect(Collectors.toList());
        }
        Set<String> foreign = new TreeSet<>();
        for (String name : compiled) {
            String type = name.endsWith(".class") ? name.substring(0, name.length() - ".class".length()) : name;
            int nested = type.indexOf('$');
            String topLevel = nested < 0 ? type : type.substring(0, nested);
            if (!own.contains(topLevel)) {
                foreign.add(type.replace('/', '.'));
            }
        }
        if (foreign.isEmpty()) {
            return null;
        }
        return (foreign.size() == 1 ? "the class " : "the classes ") + String.join(", ", foreign)
                + " must not be defined there: a file you hand in may hold only its public class and the classes nested in it."
                + " Move " + (foreign.size() == 1 ? "it" : "them") + " inside that class (as a static nested class), or into your methods.";
    }
}
