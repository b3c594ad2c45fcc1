package ray.grading.judge;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * How the judge starts a worker and ends it with everything it started, as the grader set it up
 * (ray.grading.WorkerSandbox writes it): the command, the environment, and the user the worker runs
 * as, if one. Ending a worker ends its process tree, and then every process of that user, which
 * nothing the student's code does can escape: a process cannot leave its user, and the user belongs
 * to this grading alone. When the command starts the worker in a PID namespace of its own, ending
 * the command ends the namespace and all in it at once.
 *
 * <p>The file: lines {@code command ARG}, {@code env NAME=VALUE} and {@code user NAME}, in any order;
 * the command's arguments in their order.
 */
public final class Containment {
    private final List<String> command;
    private final Map<String, String> environment;
    private final String user;

    public Containment(List<String> command, Map<String, String> environment, String user) {
        this.command = List.copyOf(command);
        this.environment = new LinkedHashMap<>(environment);
        this.user = user;
    }

    /** The setup the grader wrote to {@code file}. */
    public static Containment read(Path file) throws IOException {
        List<String> command = new ArrayList<>();
        Map<String, String> environment = new LinkedHashMap<>();
        String user = null;
        for (String line : Files.readAllLines(file, StandardCharsets.UTF_8)) {
            if (line.startsWith("command ")) {
                command.add(line.substring("command ".length()));
            } else if (line.startsWith("env ")) {
                String entry = line.substring("env ".length());
                int equals = entry.indexOf('=');
                environment.put(entry.substring(0, equals), entry.substring(equals + 1));
            } else if (line.startsWith("user ")) {
                user = line.substring("user ".length());
            } else if (!line.isBlank()) {
                throw new IOException(file + ": a line the judge does not know: " + line);
            }
        }
        if (command.isEmpty()) {
            throw new IOException(file + " names no command for the worker");
        }
        return new Containment(command, environment, user);
    }

    /** Writes this setup for {@link #read}. */
    public void write(Path file) throws IOException {
        List<String> lines = new ArrayList<>();
        command.forEach(arg -> lines.add("command " + arg));
        environment.forEach((name, value) -> lines.add("env " + name + "=" + value));
        if (user != null) {
            lines.add("user " + user);
        }
        Files.write(file, lines, StandardCharsets.UTF_8);
    }

    List<String> command() {
        return command;
    }

    /** The worker's environment: nothing of the judge's that changes a JVM, and what the setup says. */
    void environment(Map<String, String> env) {
        env.keySet().removeIf(k -> k.startsWith("JAVA_TOOL_OPTIONS") || k.equals("_JAVA_OPTIONS") || k.equals("JDK_JAVA_OPTIONS")
                || k.equals("CLASSPATH"));
        env.putAll(environment);
    }

    /**
     * Ends the worker's process, its descendants, and every process of the worker's user; then removes
     * what the user wrote, so that the next worker (another task's, or this one's after a restart)
     * finds nothing of this one's.
     */
    void end(Process process) {
        kill(process);
        try {
            process.waitFor(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        endUsersProcesses();
        removeUsersFiles();
    }

    /**
     * Kills the worker's process and its descendants at once, from any thread. The descendants first,
     * while they are still known as such: the worker proper runs under the commands that set it up
     * (unshare, setpriv), which do not take it along when they die. By the process's handle, never by
     * {@link Process#destroyForcibly}, which also closes the pipe to the worker and waits for whoever
     * writes to it.
     */
    static void kill(Process process) {
        List<ProcessHandle> tree = process.descendants().collect(Collectors.toList());
        tree.forEach(ProcessHandle::destroyForcibly);
        process.toHandle().destroyForcibly();
    }

    /**
     * Empties the worker's home and temporary folder, and removes what the worker's user made in the
     * folders everyone may write (/tmp, /var/tmp, /dev/shm); nothing without a user of its own.
     */
    public void removeUsersFiles() {
        if (user == null) {
            return;
        }
        List<Path> own = new ArrayList<>();
        for (String variable : List.of("HOME", "TMPDIR")) {
            if (environment.containsKey(variable)) {
                own.add(Path.of(environment.get(variable)));
            }
        }
        for (Path folder : own) {
            removeEntries(folder, entry -> true);
        }
        for (String shared : List.of(System.getProperty("java.io.tmpdir"), "/tmp", "/var/tmp", "/dev/shm")) {
            removeEntries(Path.of(shared), entry -> {
                try {
                    return Files.getOwner(entry, LinkOption.NOFOLLOW_LINKS).getName().equals(user);
                } catch (IOException e) {
                    return false;
                }
            });
        }
    }

    /** Removes the entries of {@code folder} that {@code which} accepts, folders with all in them; a link itself, never what it points to. */
    private static void removeEntries(Path folder, java.util.function.Predicate<Path> which) {
        if (!Files.isDirectory(folder, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        try (Stream<Path> entries = Files.list(folder)) {
            for (Path entry : entries.filter(which).collect(Collectors.toList())) {
                try (Stream<Path> walk = Files.walk(entry)) {
                    for (Path p : (Iterable<Path>) walk.sorted(java.util.Comparator.reverseOrder())::iterator) {
                        Files.deleteIfExists(p);
                    }
                } catch (IOException | java.io.UncheckedIOException e) {
                    // Gone already, or not removable: no grade depends on it.
                }
            }
        } catch (IOException e) {
            // Not listable: nothing of the grade depends on it.
        }
    }

    /** Every process of the worker's user, ended (a detached or stopped one too); none when there is no such user. */
    public int endUsersProcesses() {
        if (user == null) {
            return 0;
        }
        int ended = 0;
        for (int round = 0; round < 50; round++) {
            List<ProcessHandle> left = ProcessHandle.allProcesses()
                    .filter(p -> p.info().user().map(user::equals).orElse(false) && running(p)).collect(Collectors.toList());
            if (left.isEmpty()) {
                break;
            }
            for (ProcessHandle p : left) {
                if (p.destroyForcibly()) {
                    ended++;
                }
            }
            for (ProcessHandle p : left) {
                for (int wait = 0; wait < 20 && running(p); wait++) {
                    try {
                        Thread.sleep(10);
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        return ended;
                    }
                }
            }
        }
        return ended;
    }

    /**
     * Whether the process can still run anything: alive, and not a zombie (dead, its exit status not yet
     * collected by a parent, which a container's first process may be slow to do).
     */
    private static boolean running(ProcessHandle p) {
        if (!p.isAlive()) {
            return false;
        }
        try {
            String stat = Files.readString(Path.of("/proc", String.valueOf(p.pid()), "stat"), StandardCharsets.UTF_8);
            int close = stat.lastIndexOf(')');
            char state = close >= 0 && close + 2 < stat.length() ? stat.charAt(close + 2) : 'R';
            return state != 'Z' && state != 'X';
        } catch (IOException e) {
            return false; // gone
        }
    }
}
