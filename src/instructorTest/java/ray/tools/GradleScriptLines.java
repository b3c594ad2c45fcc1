package ray.tools;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A Gradle (Groovy DSL) build script read line by line the way {@link BuildScriptCompatibilityTest}
 * needs it: each line's code without comments and with string contents blanked, and the blocks
 * around it, so that a construct can be judged by where it stands (at the project's top level, in a
 * task action, or under a guard that only older Gradle versions enter).
 *
 * <p>A guard is {@code if (GradleVersion.current() < GradleVersion.version('X'))} with X at most
 * 8.14: its block runs only on Gradle versions that predate every construct the denylist names, so
 * code there may use what they removed. Its {@code else} block is not guarded. This is a reader for
 * ray1's own scripts, not a Groovy parser: strings in quotes and {@code ~/slashy/} patterns are
 * understood; triple-quoted strings and block comments are not used in them.
 */
final class GradleScriptLines {
    /** The newest Gradle a guarded block may run on: below 8.14 nothing of the denylist was removed yet. */
    static final String NEWEST_GUARDED_VERSION = "8.14";
    private static final Pattern GUARD = Pattern.compile(
            "if\\s*\\(\\s*GradleVersion\\.current\\(\\)\\s*<\\s*GradleVersion\\.version\\(\\s*(['\"])([\\d.]+)\\1\\s*\\)\\s*\\)");
    private static final Pattern APPLY_FROM = Pattern.compile("apply\\s+from\\s*:\\s*['\"]([^'\"]+)['\"]");
    private static final Pattern ACTION = Pattern.compile("(^|\\.)(doFirst|doLast)$|^(afterTest|afterSuite|beforeTest|beforeSuite)\\s*:$");
    private static final Pattern PLAIN_BLOCK = Pattern.compile("^(if\\s*\\(.*\\)|else|else\\s+if\\s*\\(.*\\))$");

    /** One line: its number, its text, its code (comments gone, strings blanked) and where it stands. */
    record Line(int number, String text, String code, boolean guarded, boolean inAction, boolean topLevel) {
    }

    private final Path file;
    private final List<Line> lines;
    private final List<String> appliedUnguarded = new ArrayList<>();
    private final List<String> appliedGuarded = new ArrayList<>();

    private GradleScriptLines(Path file, List<Line> lines) {
        this.file = file;
        this.lines = lines;
    }

    static GradleScriptLines read(Path file) throws IOException {
        return parse(file, Files.readString(file, StandardCharsets.UTF_8));
    }

    static GradleScriptLines parse(Path file, String text) {
        List<Line> lines = new ArrayList<>();
        GradleScriptLines script = new GradleScriptLines(file, lines);
        /** Each open block: its label (the code before its brace) and whether it is a guard. */
        Deque<String> labels = new ArrayDeque<>();
        Deque<Boolean> guards = new ArrayDeque<>();
        String[] texts = text.split("\r?\n", -1);
        for (int n = 0; n < texts.length; n++) {
            String code = codeOf(texts[n]);
            boolean guarded = guards.contains(Boolean.TRUE);
            boolean inAction = labels.stream().anyMatch(l -> ACTION.matcher(l).find());
            boolean topLevel = labels.stream().allMatch(l -> PLAIN_BLOCK.matcher(l).matches());
            Matcher apply = APPLY_FROM.matcher(texts[n]);
            if (apply.find() && code.contains("apply")) {
                (guarded ? script.appliedGuarded : script.appliedUnguarded).add(apply.group(1));
            }
            for (int i = 0; i < code.length(); i++) {
                char c = code.charAt(i);
                if (c == '{') {
                    // The label from the line itself (strings intact, at the same positions as in code),
                    // since a guard's version is a string.
                    String label = labelBefore(texts[n], i);
                    labels.push(label);
                    guards.push(isGuard(label));
                    // A block opened and used on one line ("t.doFirst { ... }") counts for that line.
                    guarded |= isGuard(label);
                    inAction |= ACTION.matcher(label).find();
                } else if (c == '}' && !labels.isEmpty()) {
                    labels.pop();
                    guards.pop();
                }
            }
            lines.add(new Line(n + 1, texts[n], code, guarded, inAction, topLevel));
        }
        return script;
    }

    /** Whether {@code label} opens a guarded block; a guard on a newer version than {@link #NEWEST_GUARDED_VERSION} does not count. */
    private static boolean isGuard(String label) {
        Matcher guard = GUARD.matcher(label);
        return guard.find() && compareVersions(guard.group(2), NEWEST_GUARDED_VERSION) <= 0;
    }

    static int compareVersions(String a, String b) {
        String[] x = a.split("\\.");
        String[] y = b.split("\\.");
        for (int i = 0; i < Math.max(x.length, y.length); i++) {
            int d = Integer.compare(i < x.length ? Integer.parseInt(x[i]) : 0, i < y.length ? Integer.parseInt(y[i]) : 0);
            if (d != 0) {
                return d;
            }
        }
        return 0;
    }

    /** The text before position {@code end} back to the previous brace, semicolon or opening bracket: a block's label. */
    private static String labelBefore(String text, int end) {
        int start = end;
        while (start > 0 && "{};[".indexOf(text.charAt(start - 1)) < 0) {
            start--;
        }
        return text.substring(start, end).trim();
    }

    /** {@code line} without its // comment, each string's content replaced by spaces (quotes kept). */
    static String codeOf(String line) {
        StringBuilder code = new StringBuilder(line.length());
        char quote = 0;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (quote != 0) {
                if (c == '\\' && i + 1 < line.length()) {
                    code.append("  ");
                    i++;
                } else if (c == quote) {
                    code.append(c);
                    quote = 0;
                } else {
                    code.append(' ');
                }
            } else if (c == '/' && i + 1 < line.length() && line.charAt(i + 1) == '/') {
                break;
            } else if (c == '\'' || c == '"') {
                quote = c;
                code.append(c);
            } else if (c == '/' && slashyStringMayStart(code)) {
                quote = '/';
                code.append(c);
            } else {
                code.append(c);
            }
        }
        return code.toString().stripTrailing();
    }

    /** A Groovy slashy string starts after ~ (a pattern) or where a value is expected: after (, a comma or =. */
    private static boolean slashyStringMayStart(StringBuilder before) {
        String text = before.toString().stripTrailing();
        return !text.isEmpty() && "~(,=".indexOf(text.charAt(text.length() - 1)) >= 0;
    }

    Path file() {
        return file;
    }

    List<Line> lines() {
        return lines;
    }

    /** The scripts this one applies ({@code apply from:}) outside any guard: they run on every Gradle. */
    List<String> appliedUnguarded() {
        return appliedUnguarded;
    }

    /** The scripts this one applies only under a guard: they run on older Gradle versions only. */
    List<String> appliedGuarded() {
        return appliedGuarded;
    }
}
