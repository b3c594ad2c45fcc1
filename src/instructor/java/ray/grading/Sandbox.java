package ray.grading;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.nio.file.attribute.UserPrincipal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import ray.grading.judge.Containment;
import ray.grading.worker.WorkerMain;

/**
 * Where and as whom a submission's code runs: the worker of each task (ray.grading.worker), started
 * by the judge as the grader sets it up here ({@link #containment}). When the grader runs as root
 * (as on both platforms), the worker runs as a user of this grading's own, {@value #USER} (or
 * {@code ray1-student-2}, ... for the other gradings gradeAll runs at once, made when missing), so
 * that ending every process of that user ends all the submission's code and no other submission's;
 * in a PID namespace of its own where the kernel allows one (ending the worker then ends everything
 * in it at once) and without network; with at most {@value #MAX_PROCESSES} processes. What it can
 * read of this folder is the classes it runs (the handout's framework and the student's own), which
 * are no secret, as root's files it cannot change; what it can write is a home and a temporary
 * folder of its own. The tests, the solution, the hidden tests and the references stay with the
 * judge, in the grader's private folder.
 *
 * <p>Without root (an instructor's own {@code gradle grade}), the worker runs as the grader's user
 * and {@link #warning} says so; ending it then ends its process tree.
 */
final class Sandbox implements AutoCloseable {
    /** The unprivileged user a submission's code runs as; gradeAll's other gradings at once use USER-2, USER-3, ... */
    static final String USER = "ray1-student";
    /** At most this many processes (threads count) for the user: a fork bomb stops there. */
    static final int MAX_PROCESSES = 2048;
    /** The worker's heap: unbounded allocation in student code fails its call, not the grader. */
    static final String HEAP = "-Xmx1g";

    /** The most users one machine's gradings at once may claim. */
    private static final int MAX_USERS = 64;

    private final Path folder;
    private final Optional<int[]> user;
    private final String userName;
    private final String warning;
    private final UserClaim claim;

    private Sandbox(Path folder, Optional<int[]> user, String userName, String warning, UserClaim claim) {
        this.folder = folder;
        this.user = user;
        this.userName = userName;
        this.warning = warning;
        this.claim = claim;
    }

    /** The user of grading slot {@code slot} (0 for a single grading). */
    static String userOf(int slot) {
        return slot == 0 ? USER : USER + "-" + (slot + 1);
    }

    /**
     * A new sandbox in the system's temporary folder for a submission's workers, which run on
     * {@code handout} (a copy is made): isolated when the grader is root and isolation is wanted, as
     * the user of {@code slot} (made when it does not exist yet), or of the next slot whose user no
     * other grading on this machine holds ({@link UserClaim}).
     */
    static Sandbox create(Path handout, boolean isolate, int slot) throws IOException {
        Optional<int[]> user = Optional.empty();
        String name = userOf(slot);
        String warning = null;
        UserClaim claim = null;
        if (!isolate) {
            warning = "student code runs as this grader's own user (isolation turned off)";
        } else if (!isRoot()) {
            warning = "student code runs as this grader's own user, not a separate one (grade as root, with the user "
                    + USER + " that setup.sh makes, to keep it from the grader's files)";
        } else if (command("setpriv") == null) {
            warning = "student code runs as root: setpriv (util-linux) is missing";
        } else {
            for (int s = slot; claim == null; s++) {
                if (s >= slot + MAX_USERS) {
                    throw new IOException("every student user from " + userOf(slot) + " on is in use by another grading");
                }
                name = userOf(s);
                claim = UserClaim.tryClaim(name);
            }
            user = lookUp(name);
            if (user.isEmpty() && !name.equals(USER)) {
                user = makeUser(name);
            }
            if (user.isEmpty()) {
                claim.close();
                claim = null;
                warning = "student code runs as root: there is no user " + name + " (setup.sh makes it: useradd --system " + name + ")";
            }
        }
        Path folder = Files.createTempDirectory("ray1-sandbox-");
        Sandbox sandbox = new Sandbox(folder, user, user.isPresent() ? name : null, warning, claim);
        try {
            Files.setPosixFilePermissions(folder, PosixFilePermissions.fromString("rwxr-xr-x"));
            ProjectTree.copyRecursively(handout, folder.resolve("handout"));
            Files.createDirectories(folder.resolve("home"));
            Files.createDirectories(folder.resolve("tmp"));
            readOnly(folder.resolve("handout"));
            if (user.isPresent()) {
                // Its own folders, which no other user (another slot's submission) may enter.
                for (String own : List.of("home", "tmp")) {
                    handOver(folder.resolve(own), sandbox);
                    Files.setPosixFilePermissions(folder.resolve(own), PosixFilePermissions.fromString("rwx------"));
                }
            }
            // Whatever a crashed grading left running as this user ends before this one starts.
            sandbox.endStrayProcesses();
        } catch (IOException | RuntimeException e) {
            ProjectTree.deleteRecursively(folder);
            if (claim != null) {
                claim.close();
            }
            throw e;
        }
        return sandbox;
    }

    /** True when workers run as a user of their own. */
    boolean isolated() {
        return user.isPresent();
    }

    /** One line for the grader's log when student code is not isolated; null when it is. */
    String warning() {
        return warning;
    }

    /**
     * How the judge starts a worker that runs {@code classes} (the student's, or a known mistake's)
     * first and the handout's framework after them: the classes are copied here as {@code name}, where
     * the worker's user can read them and not change them.
     */
    Containment containment(Path classes, String name) throws IOException {
        Path copy = folder.resolve(name);
        ProjectTree.deleteRecursively(copy);
        ProjectTree.copyRecursively(classes, copy);
        readOnly(copy);
        List<String> command = new ArrayList<>();
        if (user.isPresent()) {
            command.addAll(Namespaces.prefix());
            String prlimit = command("prlimit");
            if (prlimit != null) {
                command.addAll(List.of(prlimit, "--nproc=" + MAX_PROCESSES + ":" + MAX_PROCESSES, "--"));
            }
            int[] ids = user.get();
            command.addAll(List.of(command("setpriv"), "--reuid=" + ids[0], "--regid=" + ids[1], "--clear-groups", "--no-new-privs", "--"));
        }
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        // The JVM's own messages go to standard error (its warnings default to standard output), since standard
        // output carries only the protocol; and no performance-data file, which workers in PID namespaces of
        // their own (each one's JVM is the same pid) would contend for.
        command.addAll(List.of(HEAP, "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-XX:+DisplayVMOutputToStderr", "-Xlog:disable", "-Xlog:all=warning:stderr", "-XX:-UsePerfData",
                "-Xshare:auto", "-Djava.awt.headless=true",
                "-Duser.home=" + folder.resolve("home"), "-Djava.io.tmpdir=" + folder.resolve("tmp"),
                "-cp", copy + File.pathSeparator + folder.resolve("handout"), WorkerMain.class.getName()));
        Map<String, String> environment = new LinkedHashMap<>();
        environment.put("HOME", folder.resolve("home").toString());
        environment.put("TMPDIR", folder.resolve("tmp").toString());
        if (user.isPresent()) {
            environment.put("USER", userName);
            environment.put("LOGNAME", userName);
        }
        return new Containment(command, environment, userName);
    }

    /** Ends every process of this sandbox's user (none without one); how many were ended. */
    int endStrayProcesses() {
        return new Containment(List.of("true"), Map.of(), userName).endUsersProcesses();
    }

    /** Ends what is left, removes the folder and what the user left in the shared temporary folders, and gives the user back. */
    @Override
    public void close() throws IOException {
        try {
            endStrayProcesses();
            ProjectTree.deleteRecursively(folder);
            new Containment(List.of("true"), Map.of(), userName).removeUsersFiles();
        } finally {
            if (claim != null) {
                claim.close();
            }
        }
    }

    /** Readable by everyone, writable by none but root: the classes a worker runs. */
    private static void readOnly(Path root) throws IOException {
        try (Stream<Path> walk = Files.walk(root)) {
            for (Path p : walk.collect(Collectors.toList())) {
                Files.setPosixFilePermissions(p, PosixFilePermissions.fromString(Files.isDirectory(p) ? "r-xr-xr-x" : "r--r--r--"));
            }
        }
    }

    /** Gives the folder to the sandbox's user, who writes there. */
    private static void handOver(Path root, Sandbox sandbox) throws IOException {
        UserPrincipal owner = root.getFileSystem().getUserPrincipalLookupService().lookupPrincipalByName(sandbox.userName);
        Files.setOwner(root, owner);
        Files.setAttribute(root, "unix:gid", sandbox.user.get()[1]);
    }

    /** Makes a system user with no home and no shell (as setup.sh makes {@value #USER}); empty when that fails. */
    private static Optional<int[]> makeUser(String name) {
        String useradd = command("useradd");
        if (useradd == null) {
            return Optional.empty();
        }
        try {
            Process p = new ProcessBuilder(useradd, "--system", "--no-create-home", "--shell", "/usr/sbin/nologin", name)
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            p.waitFor(30, TimeUnit.SECONDS);
        } catch (IOException e) {
            return Optional.empty();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return Optional.empty();
        }
        return lookUp(name);
    }

    /** Whether this process runs as root (Linux: /proc/self belongs to the process's user). */
    static boolean isRoot() {
        try {
            return Integer.valueOf(0).equals(Files.getAttribute(Path.of("/proc/self"), "unix:uid"));
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException e) {
            return false;
        }
    }

    /** The user's uid and gid from /etc/passwd, if there is such a user. */
    static Optional<int[]> lookUp(String name) {
        try {
            for (String line : Files.readAllLines(Path.of("/etc/passwd"))) {
                String[] fields = line.split(":");
                if (fields.length >= 4 && fields[0].equals(name)) {
                    return Optional.of(new int[] {Integer.parseInt(fields[2]), Integer.parseInt(fields[3])});
                }
            }
        } catch (IOException | NumberFormatException e) {
            // No readable /etc/passwd: not a system where the user can be made.
        }
        return Optional.empty();
    }

    /** The program's path on the usual system folders, or null. */
    static String command(String name) {
        for (String dir : List.of("/usr/bin", "/bin", "/usr/sbin", "/sbin")) {
            if (Files.isExecutable(Path.of(dir, name))) {
                return Path.of(dir, name).toString();
            }
        }
        return null;
    }
}
