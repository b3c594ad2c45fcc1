package ray.testing;

import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.CodeSource;

/**
 * The project folder (the one holding {@code scenes/} and {@code settings.gradle}), found from
 * wherever the tests run. Tests name their files through it ({@code ProjectFolder.resolve("scenes")})
 * rather than as paths relative to the working folder, because only Gradle promises that the working
 * folder is the project: an IDE may run a test class from a subfolder, its workspace or its own
 * folder, where {@code Path.of("scenes")} names nothing and every render test would fail with a
 * missing scene.
 *
 * <p>It looks, in order, at the working folder, its parents, and the parents of the folder the test
 * classes were loaded from (build/classes/java/test for Gradle, bin/test for Eclipse and VS Code,
 * out/test/classes for IntelliJ, all inside the project), and takes the first that holds both. When
 * none does, the test fails with one line that says which folder it looked for and where.
 */
public final class ProjectFolder {
    /** What makes a folder the project: the scenes the tests read, and Gradle's settings file beside them. */
    static final String SCENES = "scenes";
    static final String SETTINGS = "settings.gradle";

    /** Found once: the working folder and the classes' location do not change while the tests run. */
    private static volatile Path found;

    private ProjectFolder() {
    }

    /** The project folder, absolute. */
    public static Path get() {
        Path folder = found;
        if (folder == null) {
            folder = find(Path.of("").toAbsolutePath(), classesLocation());
            found = folder;
        }
        return folder;
    }

    /** A path inside the project folder, named as for {@link Path#of(String, String...)}: {@code resolve("scenes", "meshes")}. */
    public static Path resolve(String first, String... more) {
        return get().resolve(Path.of(first, more));
    }

    /**
     * The first of {@code workingFolder}, its parents, and the parents of {@code classes} (null when
     * unknown) that holds scenes/ and settings.gradle; otherwise a {@link NotThisTasksFault}, since no
     * task's code is to blame.
     */
    static Path find(Path workingFolder, Path classes) {
        for (Path start : new Path[] {workingFolder, classes}) {
            for (Path p = start == null ? null : start.toAbsolutePath().normalize(); p != null; p = p.getParent()) {
                if (isProject(p)) {
                    return p;
                }
            }
        }
        throw new NotThisTasksFault("cannot find the ray1 project folder (the one with " + SCENES + "/ and " + SETTINGS
                + ") in or above the working folder " + workingFolder.toAbsolutePath()
                + (classes == null ? "" : " or the test classes' folder " + classes)
                + "; open the ray1 folder itself in your IDE, or run the tests from it");
    }

    static boolean isProject(Path folder) {
        return Files.isDirectory(folder.resolve(SCENES)) && Files.isRegularFile(folder.resolve(SETTINGS));
    }

    /** Where this class was loaded from (a classes folder or a jar), or null when the JVM does not say. */
    private static Path classesLocation() {
        CodeSource source = ProjectFolder.class.getProtectionDomain().getCodeSource();
        if (source == null || source.getLocation() == null) {
            return null;
        }
        try {
            return Path.of(source.getLocation().toURI());
        } catch (URISyntaxException | IllegalArgumentException | java.nio.file.FileSystemNotFoundException e) {
            // Not a file on this computer (a jar inside a jar, say): the working folder is all there is.
            return null;
        }
    }
}
