package ray.grading;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Run in a sandboxed test JVM by SandboxTest: prints, a line each, who it runs as, whether it can
 * read each path given, whether the hidden tests are classes here but not resources, and then
 * starts a detached process (its own session) that outlives it unless the sandbox ends it.
 */
public final class SandboxProbe {
    private SandboxProbe() {
    }

    public static void main(String[] args) throws Exception {
        System.out.println("user " + System.getProperty("user.name"));
        for (String arg : args) {
            System.out.println("readable " + arg + " " + Files.isReadable(Path.of(arg)) + " " + canList(Path.of(arg)));
        }
        ClassLoader loader = Thread.currentThread().getContextClassLoader();
        System.out.println("class " + (Class.forName("ray.hidden.Task1HiddenTest", false, loader) != null));
        System.out.println("resource " + (loader.getResource("ray/hidden/Task1HiddenTest.class") != null));
        System.out.println("loader " + SandboxProbe.class.getClassLoader().getName());
        new ProcessBuilder("setsid", "sleep", "300").start();
        System.out.println("started");
    }

    private static boolean canList(Path p) {
        try (java.util.stream.Stream<Path> s = Files.list(p)) {
            return s.count() >= 0;
        } catch (Exception e) {
            return false;
        }
    }
}
