package ray.variants;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import ray.grading.SolutionMarkers;

/**
 * Student files other than the solution, compiled against the build, and class loaders that put
 * them in the solution's place: for tests of framework code that must tell the handout's stubs
 * (or broken code) from finished work, run in this JVM.
 */
public final class StubBuild {
    private StubBuild() {
    }

    /** The handout's version of a student file ({@code src/main/java/...}, relative to the project): its stub. */
    public static String stubOf(String file) throws IOException {
        return SolutionMarkers.studentVersion(Files.readString(Path.of(file), StandardCharsets.UTF_8), file);
    }

    /**
     * Compiles {@code sources} (a path under src/main/java, such as
     * {@code src/main/java/ray/surface/Sphere.java}, to its text) against the build into the new
     * folder {@code out}, and returns it.
     */
    public static Path compile(Map<String, String> sources, Path out) throws IOException {
        Path src = Files.createDirectories(out.resolveSibling(out.getFileName() + "-src"));
        List<String> files = new ArrayList<>();
        for (Map.Entry<String, String> source : sources.entrySet()) {
            Path file = src.resolve(source.getKey().replaceFirst("^src/main/java/", ""));
            Files.createDirectories(file.getParent());
            Files.writeString(file, source.getValue(), StandardCharsets.UTF_8);
            files.add(file.toString());
        }
        String errors = javac(files, out);
        if (errors != null) {
            throw new IllegalStateException(sources.keySet() + " do not compile:\n" + errors);
        }
        return out;
    }

    /** Compiles {@code sources} against the build's classes into {@code out}: null, or javac's messages when that fails. */
    static String javac(List<String> sources, Path out) throws IOException {
        Files.createDirectories(out);
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        List<String> args = new ArrayList<>(List.of("--release", "17", "-encoding", "UTF-8", "-proc:none",
                "-classpath", System.getProperty("java.class.path"), "-d", out.toString()));
        args.addAll(sources);
        ByteArrayOutputStream messages = new ByteArrayOutputStream();
        int status = javac.run(null, messages, messages, args.toArray(new String[0]));
        return status == 0 ? null : messages.toString(StandardCharsets.UTF_8);
    }

    /**
     * A loader of every {@code ray.*} class afresh, from {@code classFolders} first and then the
     * build's own class folders (libraries are shared with this JVM): framework classes loaded by it
     * run with those folders' student classes. Close it when done.
     */
    public static URLClassLoader loader(List<Path> classFolders) throws IOException {
        List<URL> urls = new ArrayList<>();
        for (Path folder : classFolders) {
            urls.add(folder.toUri().toURL());
        }
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
            urls.add(Path.of(entry).toUri().toURL());
        }
        return new VariantLoader(urls.toArray(new URL[0]), StubBuild.class.getClassLoader());
    }
}
