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
 * use: plain, reversed, base64 (also reversed) and hex (also reversed). A secret is any
 * {@value #WINDOW}-byte window of a hidden test's source or class file, or of a solution block.
 */
final class LeakFinder {
    static final int WINDOW = 64;
    private static final Pattern BASE64 = Pattern.compile("[A-Za-z0-9+/]{" + WINDOW + ",}={0,2}");
    private static final Pattern HEX = Pattern.compile("[0-9a-fA-F]{" + (2 * WINDOW) + ",}");

    private final Set<String> windows = new HashSet<>();
    private final int secretBytes;

    private LeakFinder(List<byte[]> secrets) {
        int total = 0;
        for (byte[] secret : secrets) {
            total += secret.length;
            String text = new String(secret, StandardCharsets.ISO_8859_1);
            for (int i = 0; i + WINDOW <= text.length(); i++) {
                windows.add(text.substring(i, i + WINDOW));
            }
        }
        this.secretBytes = total;
    }

    /** The secrets of the project: hidden tests (sources, and classes as this JVM loads them) and solution blocks. */
    static LeakFinder of(Path project) throws IOException {
        List<byte[]> secrets = new ArrayList<>();
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
        for (String file : StudentFiles.in(project).keySet()) {
            String text = Files.readString(project.resolve(file), StandardCharsets.UTF_8);
            Matcher block = Pattern.compile(Pattern.quote(SolutionMarkers.BEGIN) + "(.*?)" + Pattern.quote(SolutionMarkers.END),
                    Pattern.DOTALL).matcher(text);
            while (block.find()) {
                secrets.add(block.group(1).getBytes(StandardCharsets.UTF_8));
            }
        }
        return new LeakFinder(secrets);
    }

    /** For tests of the finder itself. */
    static LeakFinder of(List<byte[]> secrets) {
        return new LeakFinder(secrets);
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
                for (int offset = 0; offset < 4; offset++) {
                    String aligned = run.substring(offset, offset + (run.length() - offset) / 4 * 4);
                    if (carries(Base64.getDecoder().decode(aligned))) {
                        return "base64" + how;
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

    private static byte[] hexDecode(String hex) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (int i = 0; i + 1 < hex.length(); i += 2) {
            out.write(Integer.parseInt(hex.substring(i, i + 2), 16));
        }
        return out.toByteArray();
    }
}
