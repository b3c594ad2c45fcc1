package ray.variants;

import static org.junit.Assert.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * The grader compiles the whole framework with a student's files in place, so the framework may use
 * nothing in a student file beyond what every student's copy has. Each variant (written as
 * students write, from the handout's files) must compile with all of src/main/java; a framework
 * class that calls a helper added to a student file later would fail here, not in a student's grade.
 */
public class VariantsCompileWithTheFrameworkTest {
    private static final Path MAIN = Path.of("src/main/java");

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void everyVariantCompilesWithTheWholeFramework() throws Exception {
        List<Path> variants;
        try (Stream<Path> entries = Files.list(Variant.ROOT)) {
            variants = entries.filter(Files::isDirectory).sorted().collect(Collectors.toList());
        }
        assertTrue("no variants under " + Variant.ROOT, variants.size() > 10);
        StringBuilder problems = new StringBuilder();
        for (Path variant : variants) {
            Map<Path, Path> sources = new LinkedHashMap<>();
            try (Stream<Path> files = Files.walk(MAIN)) {
                files.filter(p -> p.toString().endsWith(".java")).forEach(p -> sources.put(MAIN.relativize(p), p));
            }
            try (Stream<Path> files = Files.walk(variant)) {
                files.filter(p -> p.toString().endsWith(".java")).forEach(p -> sources.put(variant.relativize(p), p));
            }
            String errors = compile(new ArrayList<>(sources.values()), folder.newFolder().toPath());
            if (errors != null) {
                problems.append("\n").append(variant.getFileName()).append(":\n").append(errors);
            }
        }
        assertTrue("the framework does not compile with these students' files:" + problems, problems.length() == 0);
    }

    /** javac's messages, or null when the files compile. */
    private static String compile(List<Path> sources, Path out) {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        List<String> args = new ArrayList<>(List.of("--release", "17", "-encoding", "UTF-8", "-proc:none", "-nowarn",
                "-classpath", System.getProperty("java.class.path"), "-d", out.toString()));
        sources.forEach(p -> args.add(p.toString()));
        ByteArrayOutputStream messages = new ByteArrayOutputStream();
        int status = javac.run(null, messages, messages, args.toArray(new String[0]));
        return status == 0 ? null : messages.toString(StandardCharsets.UTF_8);
    }
}
