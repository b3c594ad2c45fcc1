package ray.grading;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;

/**
 * The processes of the student users (ray1-student, ray1-student-2, …) that can still run. A zombie
 * is not one of them: it has ended and only waits for its parent to read its exit status, which a
 * container's first process may never do.
 */
final class StudentUserProcesses {
    private StudentUserProcesses() {
    }

    /** Each living process of a user whose name starts with {@code userPrefix}, as "pid user command line". */
    static List<String> living(String userPrefix) {
        return ProcessHandle.allProcesses()
                .filter(p -> p.isAlive() && p.info().user().map(u -> u.startsWith(userPrefix)).orElse(false) && !ended(p))
                .map(p -> p.pid() + " " + p.info().user().orElse("") + " " + p.info().commandLine().orElse("?"))
                .collect(Collectors.toList());
    }

    /**
     * The living processes of {@code userPrefix}'s users once none is left or {@code seconds} have
     * passed: a process sent SIGKILL may take a moment to go (a large heap takes time to free).
     */
    static List<String> livingAfter(String userPrefix, double seconds) throws InterruptedException {
        long deadline = System.nanoTime() + (long) (seconds * 1e9);
        List<String> left = living(userPrefix);
        while (!left.isEmpty() && System.nanoTime() < deadline) {
            Thread.sleep(100);
            left = living(userPrefix);
        }
        return left;
    }

    private static boolean ended(ProcessHandle p) {
        try {
            String stat = Files.readString(Path.of("/proc", String.valueOf(p.pid()), "stat"));
            return stat.charAt(stat.lastIndexOf(')') + 2) == 'Z';
        } catch (java.io.IOException | RuntimeException e) {
            return true; // gone already
        }
    }
}
