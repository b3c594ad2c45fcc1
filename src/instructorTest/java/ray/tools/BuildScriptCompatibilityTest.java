package ray.tools;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * ray1's one build must run on Debian's Gradle 4.4.1 and on the Gradle 9 its wrapper pins, which
 * cannot be downloaded where ray1 is built. So every build script, the instructor's and the
 * generated handout's, is read for the constructs Gradle 8.14 and 9.x removed or deprecated
 * ({@link GradleDenylist}); each may stand only under a version guard that those versions never
 * enter. Scripts applied only under a guard (gradle/legacy-*.gradle) are for Gradle 4 alone.
 */
public class BuildScriptCompatibilityTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();
    private static final Path PROJECT = Path.of(".");
    private static Path handout;

    @BeforeClass
    public static void buildHandout() throws IOException {
        handout = FOLDER.getRoot().toPath().resolve("ray1");
        Handout.build(PROJECT, handout);
    }

    @Test
    public void theInstructorsScriptsUseNothingGradle9RemovedOutsideAGuard() throws IOException {
        assertNoDeniedConstruct(PROJECT);
    }

    @Test
    public void theHandoutsScriptsUseNothingGradle9RemovedOutsideAGuard() throws IOException {
        assertNoDeniedConstruct(handout);
    }

    @Test
    public void everyScriptIsReadOrKnownToBeForOldGradleOnly() throws IOException {
        Scripts scripts = Scripts.of(PROJECT);
        Set<String> read = scripts.names;
        assertTrue(read.toString(), read.containsAll(List.of("build.gradle", "settings.gradle", "gradle/test-report.gradle",
                "gradle/submission.gradle", "gradle/instructor.gradle")));
        assertEquals(Set.of("gradle/legacy-run.gradle", "gradle/legacy-test-worker.gradle"), scripts.oldGradleOnly);
        try (Stream<Path> files = Files.list(PROJECT.resolve("gradle"))) {
            for (Path file : (Iterable<Path>) files.filter(f -> f.toString().endsWith(".gradle"))::iterator) {
                String name = "gradle/" + file.getFileName();
                assertTrue(name + " is applied by no script: read it or remove it", read.contains(name) || scripts.oldGradleOnly.contains(name));
            }
        }
    }

    @Test
    public void eachEntryFindsItsOwnExampleAndAGuardExemptsIt() {
        for (GradleDenylist.Entry entry : GradleDenylist.ENTRIES) {
            String unguarded = entry.where() == GradleDenylist.Where.IN_ACTION && !entry.example().contains("doFirst")
                    ? "t.doFirst {\n" + entry.example() + "\n}\n" : entry.example() + "\n";
            assertTrue(entry.name() + " misses its example: " + entry.example(), !problems(parse(unguarded)).isEmpty());
            String guarded = "if (GradleVersion.current() < GradleVersion.version('6.4')) {\n" + unguarded + "}\n";
            assertEquals(entry.name() + " under a guard", List.of(), problems(parse(guarded)));
        }
    }

    @Test
    public void theElseOfAGuardAndAGuardOnANewerGradleAreNotExempt() {
        String elseBranch = "if (GradleVersion.current() < GradleVersion.version('6.4')) {\n    mainClassName = 'x'\n} else {\n"
                + "    mainClassName = 'x'\n}\n";
        List<String> found = problems(parse(elseBranch));
        assertEquals(found.toString(), 1, found.size());
        assertTrue(found.get(0), found.get(0).startsWith("build.gradle:4:"));
        assertEquals(1, problems(parse("if (GradleVersion.current() < GradleVersion.version('9.1')) {\n    jcenter()\n}\n")).size());
    }

    @Test
    public void onlyTheRealConstructIsFlagged() {
        // Inside application {} the property is the extension's, not the removed convention; strings and
        // comments are not code; doFirst reading local values is what the rule asks for.
        String fine = "application {\n    applicationDefaultJvmArgs = ['-Xmx1g']\n}\n"
                + "println 'the buildDir is gone' // compile 'x'\n"
                + "def out = file('build/x')\n"
                + "t.doFirst {\n    t.args = [out.path]\n}\n"
                + "test.testLogging {\n    events 'failed'\n    exceptionFormat = 'full'\n}\n"
                + "import org.gradle.util.GradleVersion\n";
        assertEquals(List.of(), problems(parse(fine)));
        assertEquals(1, problems(parse("t.doFirst {\n    t.args = [file('x').path]\n}\n")).size());
        assertEquals(1, problems(parse("t.addTestListener([\n    afterSuite: { s, r ->\n        println project.name\n    }] as TestListener)\n")).size());
    }

    /**
     * The JUnit launch of Gradle 4 (legacy-test-worker.gradle) and its class selection pick test classes
     * by name: a class with tests must be called *Test, or no Gradle 4 run would find it.
     */
    @Test
    public void everyTestClassIsNamedSoThatGradle4FindsIt() throws IOException {
        Pattern hasTests = Pattern.compile("^\\s*@(org\\.junit\\.)?(Test|RunWith)\\b", Pattern.MULTILINE);
        List<String> misnamed = new ArrayList<>();
        for (String root : List.of("src/test/java", "src/instructorTest/java", "src/instructorBrowserTest/java")) {
            try (Stream<Path> files = Files.walk(PROJECT.resolve(root))) {
                for (Path file : (Iterable<Path>) files.filter(f -> f.toString().endsWith(".java"))::iterator) {
                    String text = Files.readString(file);
                    boolean abstractClass = text.contains("abstract class " + file.getFileName().toString().replace(".java", ""));
                    if (hasTests.matcher(text).find() && !abstractClass && !file.toString().endsWith("Test.java")) {
                        misnamed.add(file.toString());
                    }
                }
            }
        }
        assertEquals(List.of(), misnamed);
    }

    private static GradleScriptLines parse(String text) {
        return GradleScriptLines.parse(Path.of("build.gradle"), text);
    }

    private static void assertNoDeniedConstruct(Path project) throws IOException {
        List<String> found = new ArrayList<>();
        for (GradleScriptLines script : Scripts.of(project).checked) {
            found.addAll(problems(script));
        }
        assertEquals("constructs Gradle 8.14 or 9 removed or deprecated, outside a GradleVersion guard", List.of(), found);
    }

    /** "file:line: the construct (source): the line" for each line an entry flags. */
    private static List<String> problems(GradleScriptLines script) {
        List<String> found = new ArrayList<>();
        for (GradleScriptLines.Line line : script.lines()) {
            for (GradleDenylist.Entry entry : GradleDenylist.ENTRIES) {
                if (entry.flags(line)) {
                    found.add(script.file() + ":" + line.number() + ": " + entry.name() + " (" + entry.source() + "): "
                            + line.text().trim());
                }
            }
        }
        return found;
    }

    /** A project's scripts: build.gradle and settings.gradle and what they apply unguarded, and those applied only under a guard. */
    private static final class Scripts {
        final List<GradleScriptLines> checked = new ArrayList<>();
        final Set<String> names = new LinkedHashSet<>();
        final Set<String> oldGradleOnly = new LinkedHashSet<>();

        static Scripts of(Path project) throws IOException {
            Scripts scripts = new Scripts();
            Deque<String> toRead = new ArrayDeque<>(List.of("build.gradle", "settings.gradle"));
            Set<String> seen = scripts.names;
            while (!toRead.isEmpty()) {
                String name = toRead.pop();
                if (!seen.add(name)) {
                    continue;
                }
                GradleScriptLines script = GradleScriptLines.read(project.resolve(name));
                scripts.checked.add(script);
                toRead.addAll(script.appliedUnguarded());
                scripts.oldGradleOnly.addAll(script.appliedGuarded());
            }
            scripts.oldGradleOnly.removeAll(seen);
            return scripts;
        }
    }
}
