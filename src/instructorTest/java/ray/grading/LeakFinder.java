package ray.grading;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * Looks for the grader's secrets in text a student sees, in the encodings a leaking submission would
 * use: plain, reversed, base64 (also reversed, also of gzipped bytes) and hex (also reversed). A
 * secret is any {@value #WINDOW}-byte window of a hidden test's source or class file, of a solution
 * block, or of a solution class file, that neither the handout's own classes and visible tests (which
 * every student has) nor the JDK's class files hold: a window the JDK holds too is the boilerplate of every class file
 * (the bootstrap of a string concatenation, say), which code reading its own process's memory finds in
 * the JDK's image mapped there.
 */
final class LeakFinder {
    static final int WINDOW = 64;
    /** Base64 runs long enough to carry a gzipped window (a window's gzip can be shorter than the window). */
    private static final Pattern BASE64 = Pattern.compile("[A-Za-z0-9+/]{24,}={0,2}");
    /** The most a gzipped run is unpacked to. */
    private static final int MAX_GUNZIPPED = 16 << 20;
    private static final Pattern HEX = Pattern.compile("[0-9a-fA-F]{" + (2 * WINDOW) + ",}");

    private final Set<String> windows = new HashSet<>();
    private final int secretBytes;

    private LeakFinder(List<byte[]> secrets, List<byte[]> known) {
        int total = 0;
        for (byte[] secret : secrets) {
            total += secret.length;
            String text = new String(secret, StandardCharsets.ISO_8859_1);
            for (int i = 0; i + WINDOW <= text.length(); i++) {
                windows.add(text.substring(i, i + WINDOW));
            }
        }
        known.forEach(this::removeWindowsOf);
        this.secretBytes = total;
    }

    /**
     * Counts {@code text} as known: what every student sees (the visible tests' messages to the stub
     * handout) may say what a hidden test's source says too, an input described alike.
     */
    void know(String text) {
        removeWindowsOf(text.getBytes(StandardCharsets.UTF_8));
        removeWindowsOf(text.getBytes(StandardCharsets.ISO_8859_1));
    }

    private void removeWindowsOf(byte[] open) {
        String text = new String(open, StandardCharsets.ISO_8859_1);
        for (int i = 0; i + WINDOW <= text.length(); i++) {
            windows.remove(text.substring(i, i + WINDOW));
        }
    }

    /** Powers of this odd number weigh a window's bytes in its hash (Rabin–Karp rolling hash, modulo 2^64). */
    private static final long HASH_BASE = 0x100000001b3L;

    /**
     * Removes every window that the running JDK's image of class files ({@code lib/modules}) holds:
     * each window's hash goes in a table, then one pass over the image with a rolling hash finds those
     * it holds (a hash that matches by chance removes a window too: one in 2^64).
     */
    private void removeJdkWindows() throws IOException {
        Path image = Path.of(System.getProperty("java.home"), "lib", "modules");
        if (windows.isEmpty() || !Files.isRegularFile(image)) {
            return;
        }
        long[] table = new long[Integer.highestOneBit(windows.size() * 2) << 1];
        for (String w : windows) {
            insert(table, hash(w));
        }
        long top = 1;
        for (int i = 1; i < WINDOW; i++) {
            top *= HASH_BASE;
        }
        Set<Long> found = new HashSet<>();
        try (java.nio.channels.FileChannel channel = java.nio.channels.FileChannel.open(image)) {
            java.nio.MappedByteBuffer bytes = channel.map(java.nio.channels.FileChannel.MapMode.READ_ONLY, 0, channel.size());
            long h = 0;
            int n = bytes.limit();
            for (int i = 0; i < n; i++) {
                if (i >= WINDOW) {
                    h -= (bytes.get(i - WINDOW) & 0xff) * top;
                }
                h = h * HASH_BASE + (bytes.get(i) & 0xff);
                if (i >= WINDOW - 1 && contains(table, h)) {
                    found.add(nonZero(h));
                }
            }
        }
        windows.removeIf(w -> found.contains(hash(w)));
    }

    private static long hash(String window) {
        long h = 0;
        for (int i = 0; i < window.length(); i++) {
            h = h * HASH_BASE + (window.charAt(i) & 0xff);
        }
        return nonZero(h);
    }

    /** The table marks an empty slot with 0. */
    private static long nonZero(long h) {
        return h == 0 ? 1 : h;
    }

    private static void insert(long[] table, long h) {
        int mask = table.length - 1;
        for (int slot = (int) (h ^ (h >>> 32)) & mask; ; slot = (slot + 1) & mask) {
            if (table[slot] == 0 || table[slot] == h) {
                table[slot] = h;
                return;
            }
        }
    }

    private static boolean contains(long[] table, long h) {
        h = nonZero(h);
        int mask = table.length - 1;
        for (int slot = (int) (h ^ (h >>> 32)) & mask; table[slot] != 0; slot = (slot + 1) & mask) {
            if (table[slot] == h) {
                return true;
            }
        }
        return false;
    }

    /**
     * The secrets of the project: hidden tests (sources, and classes: the tree's compiled ones where it
     * has them, as the Gradescope bundle does, else as this JVM loads them), solution blocks and, with a
     * compiled tree, the solution's classes; less what its compiled handout holds.
     */
    static LeakFinder of(Path project) throws IOException {
        List<byte[]> secrets = new ArrayList<>();
        List<byte[]> known = new ArrayList<>();
        Path compiled = project.resolve(PrecompiledTree.FOLDER).resolve("classes");
        try (Stream<Path> hidden = Files.list(project.resolve("src/instructorTest/java/ray/hidden"))) {
            for (Path source : hidden.filter(p -> p.toString().endsWith(".java")).sorted().collect(Collectors.toList())) {
                secrets.add(Files.readAllBytes(source));
                String name = source.getFileName().toString().replace(".java", ".class");
                try (InputStream in = LeakFinder.class.getResourceAsStream("/ray/hidden/" + name)) {
                    if (in != null) {
                        secrets.add(in.readAllBytes());
                    }
                }
            }
        }
        if (Files.isDirectory(compiled)) {
            secrets.addAll(classFiles(compiled.resolve("ray/hidden"), name -> true));
            for (String file : StudentFiles.in(project).keySet()) {
                String className = Path.of(file).getFileName().toString().replace(".java", "");
                Path folder = compiled.resolve(Path.of(file.replace("src/main/java/", ""))).getParent();
                secrets.addAll(classFiles(folder, name -> name.equals(className + ".class") || name.startsWith(className + "$")));
            }
            known.addAll(classFiles(compiled.resolveSibling("handout"), name -> true));
        }
        // The handout's own tests are every student's: a hidden test that says what a visible one says keeps no secret in it.
        Path visibleTests = project.resolve("src/test/java");
        if (Files.isDirectory(visibleTests)) {
            try (Stream<Path> sources = Files.walk(visibleTests)) {
                for (Path source : sources.filter(p -> p.toString().endsWith(".java")).sorted().collect(Collectors.toList())) {
                    known.add(Files.readAllBytes(source));
                    // And compiled: the source may spell a character as an escape (\u2212) that the class file holds as UTF-8.
                    String className = source.getFileName().toString().replace(".java", "");
                    known.addAll(classFiles(compiled.resolve(visibleTests.relativize(source)).getParent(),
                            name -> name.equals(className + ".class") || name.startsWith(className + "$")));
                }
            }
        }
        for (String file : StudentFiles.in(project).keySet()) {
            String text = Files.readString(project.resolve(file), StandardCharsets.UTF_8);
            Matcher block = Pattern.compile(Pattern.quote(SolutionMarkers.BEGIN) + "(.*?)" + Pattern.quote(SolutionMarkers.END),
                    Pattern.DOTALL).matcher(text);
            while (block.find()) {
                secrets.add(block.group(1).getBytes(StandardCharsets.UTF_8));
            }
        }
        LeakFinder finder = new LeakFinder(secrets, known);
        finder.removeJdkWindows();
        return finder;
    }

    /** The bytes of the class files under {@code folder} (all its subfolders) whose names {@code named} accepts. */
    private static List<byte[]> classFiles(Path folder, java.util.function.Predicate<String> named) throws IOException {
        List<byte[]> bytes = new ArrayList<>();
        if (!Files.isDirectory(folder)) {
            return bytes;
        }
        try (Stream<Path> walk = Files.walk(folder)) {
            for (Path p : walk.filter(p -> p.toString().endsWith(".class") && named.test(p.getFileName().toString())).sorted()
                    .collect(Collectors.toList())) {
                bytes.add(Files.readAllBytes(p));
            }
        }
        return bytes;
    }

    /** For tests of the finder itself. */
    static LeakFinder of(List<byte[]> secrets) {
        return new LeakFinder(secrets, List.of());
    }

    int secretBytes() {
        return secretBytes;
    }

    /** The encoding in which {@code text} carries a secret window ("plain", "base64 reversed", ...), or null. */
    String leakIn(String text) {
        for (boolean reversed : new boolean[] {false, true}) {
            String s = reversed ? new StringBuilder(text).reverse().toString() : text;
            String how = reversed ? " reversed" : "";
            if (carries(s.getBytes(StandardCharsets.UTF_8)) || carries(s.getBytes(StandardCharsets.ISO_8859_1))) {
                return "plain" + how;
            }
            Matcher base64 = BASE64.matcher(s);
            while (base64.find()) {
                String run = base64.group().replace("=", "");
                for (int offset = 0; offset < 4 && offset < run.length(); offset++) {
                    String aligned = run.substring(offset, offset + (run.length() - offset) / 4 * 4);
                    byte[] decoded = Base64.getDecoder().decode(aligned);
                    if (carries(decoded)) {
                        return "base64" + how;
                    }
                    if (carries(gunzipped(decoded))) {
                        return "gzip base64" + how;
                    }
                }
            }
            Matcher hex = HEX.matcher(s);
            while (hex.find()) {
                for (int offset = 0; offset < 2; offset++) {
                    if (carries(hexDecode(hex.group().substring(offset)))) {
                        return "hex" + how;
                    }
                }
            }
        }
        return null;
    }

    private boolean carries(byte[] bytes) {
        String text = new String(bytes, StandardCharsets.ISO_8859_1);
        for (int i = 0; i + WINDOW <= text.length(); i++) {
            if (windows.contains(text.substring(i, i + WINDOW))) {
                return true;
            }
        }
        return false;
    }

    /** What {@code bytes} unpack to when they are a gzip stream (as much as unpacks, at most {@link #MAX_GUNZIPPED}), else nothing. */
    private static byte[] gunzipped(byte[] bytes) {
        if (bytes.length < 2 || (bytes[0] & 0xff) != 0x1f || (bytes[1] & 0xff) != 0x8b) {
            return new byte[0];
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (java.util.zip.GZIPInputStream in = new java.util.zip.GZIPInputStream(new java.io.ByteArrayInputStream(bytes))) {
            byte[] buffer = new byte[8192];
            for (int n; out.size() < MAX_GUNZIPPED && (n = in.read(buffer)) > 0;) {
                out.write(buffer, 0, n);
            }
        } catch (IOException e) {
            // A cut or broken stream: what came before the break counts.
        }
        return out.toByteArray();
    }

    private static byte[] hexDecode(String hex) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (int i = 0; i + 1 < hex.length(); i += 2) {
            out.write(Integer.parseInt(hex.substring(i, i + 2), 16));
        }
        return out.toByteArray();
    }
}
