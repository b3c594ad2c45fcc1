package ray.grading;

import java.io.DataOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.nio.file.attribute.UserPrincipal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import ray.grading.boot.InMemoryMain;

/**
 * Where a test JVM that runs student code lives, and as whom. When the grader runs as root and the
 * user {@value #USER} exists (setup.sh and the PrairieLearn Dockerfile make it), the test JVM runs
 * as that user; everything it may read is in this folder:
 * <ul>
 * <li>{@code boot/}: the one small class that starts it ({@link InMemoryMain});</li>
 * <li>{@code lib/}: copies of the public libraries (JUnit, ...);</li>
 * <li>{@code tree/}: its working folder, the scenes and settings.gradle, which the handout ships too;</li>
 * <li>{@code run/}: what it writes (the events file, a home and a temporary folder).</li>
 * </ul>
 * The compiled tree itself (framework, solution, tests, hidden tests) is never a file it can read:
 * its bytes go to the JVM's standard input and are defined in memory. After each test JVM, every
 * process left owned by that user is ended, so nothing the student started outlives its tests.
 *
 * <p>Without root (an instructor's own `gradle grade`), the same layout is used but the JVM runs as
 * the grader's user, and {@link #warning} says so: then only the JVM's own descendants are ended.
 */
final class Sandbox implements AutoCloseable {
    /** The unprivileged user student code runs as. */
    static final String USER = "ray1-student";
    /** At most this many processes (threads count) for the user: a fork bomb stops there. */
    static final int MAX_PROCESSES = 2048;

    private final Path folder;
    private final Optional<int[]> user;
    private final String warning;
    /** Public libraries already copied to lib/, by original path. */
    private final Map<String, Path> copiedLibraries = new LinkedHashMap<>();
    /** The test JVMs' descendants seen while they ran (what is ended without a user of its own). */
    private final Set<ProcessHandle> seen = new LinkedHashSet<>();
    /**
     * The test JVMs running now, of every sandbox in this grader (gradeAll grades several submissions
     * at once, all as the one user): what they and their descendants run is theirs to end, not a
     * stray of another sandbox's.
     */
    private static final Set<ProcessHandle> RUNNING = java.util.concurrent.ConcurrentHashMap.newKeySet();

    private Sandbox(Path folder, Optional<int[]> user, String warning) {
        this.folder = folder;
        this.user = user;
        this.warning = warning;
    }

    /**
     * A new sandbox in the system's temporary folder for grading {@code project}'s tests: isolated when
     * the grader is root and {@value #USER} exists, unless {@code isolate} is false.
     */
    static Sandbox create(Path project, boolean isolate) throws IOException {
        Optional<int[]> user = Optional.empty();
        String warning = null;
        if (!isolate) {
            warning = "student code runs as this grader's own user (isolation turned off)";
        } else if (!isRoot()) {
            warning = "student code runs as this grader's own user, not a separate one (grade as root, with the user "
                    + USER + " that setup.sh makes, to keep it from the grader's files)";
        } else {
            user = lookUp(USER);
            if (user.isEmpty()) {
                warning = "student code runs as root: there is no user " + USER + " (setup.sh makes it: useradd --system " + USER + ")";
            } else if (command("setpriv") == null) {
                user = Optional.empty();
                warning = "student code runs as root: setpriv (util-linux) is missing";
            }
        }
        Path folder = Files.createTempDirectory("ray1-sandbox-");
        Sandbox sandbox = new Sandbox(folder, user, warning);
        try {
            sandbox.layOut(project);
        } catch (IOException | RuntimeException e) {
            ProjectTree.deleteRecursively(folder);
            throw e;
        }
        return sandbox;
    }

    /** True when test JVMs run as {@value #USER}. */
    boolean isolated() {
        return user.isPresent();
    }

    /** One line for the grader's log when student code is not isolated; null when it is. */
    String warning() {
        return warning;
    }

    /** The tests' working folder. */
    Path tree() {
        return folder.resolve("tree");
    }

    /** Where the test JVM may write (its events files). */
    Path runFolder() {
        return folder.resolve("run");
    }

    private void layOut(Path project) throws IOException {
        Files.setPosixFilePermissions(folder, PosixFilePermissions.fromString("rwxr-xr-x"));
        copyBootClasses(folder.resolve("boot"));
        Files.createDirectories(folder.resolve("lib"));
        ProjectTree.copyRecursively(project.resolve("scenes"), tree().resolve("scenes"));
        Files.copy(project.resolve("settings.gradle"), tree().resolve("settings.gradle"));
        Files.createDirectories(runFolder().resolve("home"));
        Files.createDirectories(runFolder().resolve("tmp"));
        makeReadable(folder);
        if (user.isPresent()) {
            handOver(tree());
            handOver(runFolder());
        }
    }

    /**
     * The command that starts {@code mainClass} with {@code arguments} in a test JVM: as the user when
     * isolated, with the boot class and the public libraries of {@code classpath} on its class path.
     * Its standard input must then receive {@link #writeClasses} of the same class path.
     */
    List<String> command(List<String> jvmOptions, String classpath, String mainClass, List<String> arguments) throws IOException {
        List<String> command = new ArrayList<>();
        if (user.isPresent()) {
            String prlimit = command("prlimit");
            if (prlimit != null) {
                command.addAll(List.of(prlimit, "--nproc=" + MAX_PROCESSES + ":" + MAX_PROCESSES, "--"));
            }
            int[] ids = user.get();
            command.addAll(List.of(command("setpriv"), "--reuid=" + ids[0], "--regid=" + ids[1], "--clear-groups",
                    "--no-new-privs", "--"));
        }
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(jvmOptions);
        // No agent may attach to the test JVM and read the classes back out of it.
        command.addAll(List.of("-XX:+DisableAttachMechanism", "-Duser.home=" + runFolder().resolve("home"),
                "-Djava.io.tmpdir=" + runFolder().resolve("tmp")));
        List<String> path = new ArrayList<>(List.of(folder.resolve("boot").toString()));
        for (Path library : publicLibraries(classpath)) {
            path.add(library.toString());
        }
        command.addAll(List.of("-cp", String.join(File.pathSeparator, path), InMemoryMain.class.getName(), mainClass));
        command.addAll(arguments);
        return command;
    }

    /**
     * The environment variable naming the sandbox a process belongs to: its test JVM and whatever
     * that starts inherit it, so that a grader ends only its own strays, not another grader's running
     * tests (two graders as root on one machine share the user).
     */
    static final String MARKER = "RAY1_SANDBOX";

    /** Sets the environment a test JVM starts with: a home and temporary folder of its own, and this sandbox's marker. */
    void environment(Map<String, String> environment) {
        environment.put(MARKER, folder.toString());
        environment.keySet().removeIf(k -> k.startsWith("JAVA_TOOL_OPTIONS") || k.equals("_JAVA_OPTIONS") || k.equals("JDK_JAVA_OPTIONS"));
        environment.put("HOME", runFolder().resolve("home").toString());
        environment.put("TMPDIR", runFolder().resolve("tmp").toString());
        if (user.isPresent()) {
            environment.put("USER", USER);
            environment.put("LOGNAME", USER);
        }
    }

    /**
     * Writes every file of the class path's private entries (class folders, and jars holding ray
     * classes) in the stream {@link InMemoryMain} reads, the first of a name first, as a class path
     * would choose.
     */
    static void writeClasses(String classpath, OutputStream out) throws IOException {
        DataOutputStream data = new DataOutputStream(new java.io.BufferedOutputStream(out, 1 << 16));
        Set<String> sent = new java.util.HashSet<>();
        for (String entry : classpath.split(File.pathSeparator)) {
            if (entry.isEmpty()) {
                continue;
            }
            Path path = Path.of(entry);
            if (Files.isDirectory(path)) {
                try (Stream<Path> walk = Files.walk(path)) {
                    for (Path file : walk.filter(Files::isRegularFile).sorted().collect(Collectors.toList())) {
                        String name = path.relativize(file).toString().replace(File.separatorChar, '/');
                        if (sent.add(name)) {
                            send(data, name, Files.readAllBytes(file));
                        }
                    }
                }
            } else if (isPrivateJar(path)) {
                try (JarFile jar = new JarFile(path.toFile())) {
                    for (JarEntry e : java.util.Collections.list(jar.entries())) {
                        if (!e.isDirectory() && sent.add(e.getName())) {
                            try (InputStream in = jar.getInputStream(e)) {
                                send(data, e.getName(), in.readAllBytes());
                            }
                        }
                    }
                }
            }
        }
        data.writeBoolean(false);
        data.flush();
    }

    private static void send(DataOutputStream data, String name, byte[] bytes) throws IOException {
        data.writeBoolean(true);
        data.writeUTF(name);
        data.writeInt(bytes.length);
        data.write(bytes);
    }

    /** Notes that a test JVM runs (until {@link #ended}). */
    void started(Process child) {
        RUNNING.add(child.toHandle());
    }

    /** Notes that the test JVM has ended, or been stopped. */
    void ended(Process child) {
        RUNNING.remove(child.toHandle());
    }

    /** Notes the test JVM's descendants as they are now (called while it runs). */
    void watch(Process child) {
        child.descendants().forEach(seen::add);
    }

    /**
     * Ends every process the test JVM left behind: all of {@value #USER}'s processes when isolated
     * (a detached `setsid` child too) but the running test JVMs of other sandboxes in this grader and
     * their descendants, and the processes of other graders' live sandboxes; else the descendants
     * seen. Returns how many were ended.
     */
    int endStrayProcesses() {
        int ended = 0;
        for (int round = 0; round < 20; round++) {
            List<ProcessHandle> left = user.isPresent()
                    ? ProcessHandle.allProcesses().filter(p -> p.info().user().map(USER::equals).orElse(false))
                            .filter(p -> !ofARunningTestJvm(p) && !ofAnotherLiveSandbox(p)).collect(Collectors.toList())
                    : seen.stream().filter(ProcessHandle::isAlive).collect(Collectors.toList());
            if (left.isEmpty()) {
                break;
            }
            for (ProcessHandle p : left) {
                if (p.destroyForcibly()) {
                    ended++;
                }
            }
            for (ProcessHandle p : left) {
                try {
                    p.onExit().get(1, java.util.concurrent.TimeUnit.SECONDS);
                } catch (Exception e) {
                    // Still going (a zombie waiting for its parent): the next round looks again.
                }
            }
        }
        seen.removeIf(p -> !p.isAlive());
        return ended;
    }

    /** Whether the process is a running test JVM (of any sandbox) or one's descendant. */
    private static boolean ofARunningTestJvm(ProcessHandle process) {
        for (Optional<ProcessHandle> p = Optional.of(process); p.isPresent(); p = p.get().parent()) {
            if (RUNNING.contains(p.get())) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether the process carries the marker of another sandbox that still exists (another grader's,
     * on this machine): that grader ends it. A process without a marker, with this sandbox's, or with
     * a removed sandbox's is a stray.
     */
    private boolean ofAnotherLiveSandbox(ProcessHandle process) {
        try {
            for (String variable : new String(Files.readAllBytes(Path.of("/proc", String.valueOf(process.pid()), "environ")),
                    java.nio.charset.StandardCharsets.UTF_8).split("\0")) {
                if (variable.startsWith(MARKER + "=")) {
                    Path other = Path.of(variable.substring(MARKER.length() + 1));
                    return !other.equals(folder) && Files.isDirectory(other) && other.getFileName().toString().startsWith("ray1-sandbox-");
                }
            }
        } catch (IOException | RuntimeException e) {
            // Gone already, or no /proc: nothing to spare.
        }
        return false;
    }

    /** Ends what is left and removes the folder. */
    @Override
    public void close() throws IOException {
        endStrayProcesses();
        ProjectTree.deleteRecursively(folder);
    }

    /** The class path's public libraries (jars without ray classes), copied into lib/ once each. */
    private List<Path> publicLibraries(String classpath) throws IOException {
        List<Path> libraries = new ArrayList<>();
        for (String entry : classpath.split(File.pathSeparator)) {
            Path path = entry.isEmpty() ? null : Path.of(entry);
            if (path == null || Files.isDirectory(path) || !Files.isRegularFile(path) || isPrivateJar(path)) {
                continue;
            }
            Path copy = copiedLibraries.get(entry);
            if (copy == null) {
                copy = folder.resolve("lib").resolve(copiedLibraries.size() + "-" + path.getFileName());
                Files.copy(path, copy);
                makeReadable(copy);
                copiedLibraries.put(entry, copy);
            }
            libraries.add(copy);
        }
        return libraries;
    }

    /** A jar holding classes of ray1 itself (the grader's jar): never readable by student code. */
    static boolean isPrivateJar(Path jar) throws IOException {
        if (!Files.isRegularFile(jar) || !jar.toString().endsWith(".jar")) {
            return false;
        }
        try (JarFile file = new JarFile(jar.toFile())) {
            return file.stream().anyMatch(e -> e.getName().startsWith("ray/"));
        }
    }

    /** Copies the boot package's classes (and only those) from wherever the grader's classes are. */
    private static void copyBootClasses(Path boot) throws IOException {
        String pkg = InMemoryMain.class.getPackageName().replace('.', '/') + "/";
        Path source;
        try {
            source = Path.of(InMemoryMain.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException e) {
            throw new IOException(e);
        }
        Files.createDirectories(boot.resolve(pkg));
        if (Files.isDirectory(source)) {
            try (Stream<Path> files = Files.list(source.resolve(pkg))) {
                for (Path file : files.filter(f -> f.toString().endsWith(".class")).collect(Collectors.toList())) {
                    Files.copy(file, boot.resolve(pkg).resolve(file.getFileName().toString()));
                }
            }
        } else {
            try (JarFile jar = new JarFile(source.toFile())) {
                for (JarEntry e : java.util.Collections.list(jar.entries())) {
                    String name = e.getName();
                    if (name.startsWith(pkg) && name.endsWith(".class") && name.indexOf('/', pkg.length()) < 0) {
                        try (InputStream in = jar.getInputStream(e)) {
                            Files.write(boot.resolve(name), in.readAllBytes());
                        }
                    }
                }
            }
        }
    }

    /** World-readable (and folders enterable): the sandbox's files are no secret, and the user must read them. */
    private static void makeReadable(Path root) throws IOException {
        try (Stream<Path> walk = Files.walk(root)) {
            for (Path p : walk.collect(Collectors.toList())) {
                Files.setPosixFilePermissions(p, PosixFilePermissions.fromString(Files.isDirectory(p) ? "rwxr-xr-x" : "rw-r--r--"));
            }
        }
    }

    /** Gives the folder and everything in it to the user, who writes there. */
    private void handOver(Path root) throws IOException {
        UserPrincipal owner = root.getFileSystem().getUserPrincipalLookupService().lookupPrincipalByName(USER);
        try (Stream<Path> walk = Files.walk(root)) {
            for (Path p : walk.collect(Collectors.toList())) {
                Files.setOwner(p, owner);
                Files.setAttribute(p, "unix:gid", user.get()[1]);
            }
        }
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
    private static String command(String name) {
        for (String dir : List.of("/usr/bin", "/bin", "/usr/sbin", "/sbin")) {
            if (Files.isExecutable(Path.of(dir, name))) {
                return Path.of(dir, name).toString();
            }
        }
        return null;
    }
}
