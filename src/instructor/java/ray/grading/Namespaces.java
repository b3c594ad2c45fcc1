package ray.grading;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Linux namespaces for a worker, when this machine allows them (a container without the right to
 * make them does not; then the worker's own user is what contains it): a PID namespace, whose every
 * process the kernel ends when its first one ends, so that ending the worker ends all it started at
 * once; and a network namespace with no interface up, so that nothing the student's code learns
 * leaves by the network. Each is tried once per grader.
 */
final class Namespaces {
    private static List<String> prefix;

    private Namespaces() {
    }

    /** The command words that start a process in new namespaces, or none when they cannot be made here. */
    static synchronized List<String> prefix() {
        if (prefix == null) {
            prefix = probe();
        }
        return prefix;
    }

    private static List<String> probe() {
        String unshare = Sandbox.command("unshare");
        if (unshare == null) {
            return List.of();
        }
        List<String> both = List.of(unshare, "--pid", "--fork", "--kill-child", "--net", "--");
        if (works(both)) {
            return both;
        }
        List<String> pidOnly = List.of(unshare, "--pid", "--fork", "--kill-child", "--");
        return works(pidOnly) ? pidOnly : List.of();
    }

    private static boolean works(List<String> prefix) {
        List<String> command = new ArrayList<>(prefix);
        command.add("true");
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            return p.waitFor(10, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }
}
