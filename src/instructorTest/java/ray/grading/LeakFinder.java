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
 * block, or of a solution class file, that the handout's own classes (which every student has) do not
 * hold too.
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
        for (byte[] open : known) {
            String text = new String(open, StandardCharsets.ISO_8859_1);
            for (int i = 0; i + WINDOW <= text.length(); i++) {
                windows.remove(text.substring(i, i + WINDOW));
            }
        }
        this.secretBytes = total;
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
        for (String file : StudentFiles.in(project).keySet()) {
            String text = Files.readString(project.resolve(file), StandardCharsets.UTF_8);
            Matcher block = Pattern.compile(Pattern.quote(SolutionMarkers.BEGIN) + "(.*?)" + Pattern.quote(SolutionMarkers.END),
                    Pattern.DOTALL).matcher(text);
            while (block.find()) {
                secrets.add(block.group(1).getBytes(StandardCharsets.UTF_8));
            }
        }
        return new LeakFinder(secrets, known);
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
