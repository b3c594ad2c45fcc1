package ray.tools;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

/**
 * What Gradle 8.14 and 9.x removed or deprecated, as ray1's build scripts could spell it, each with
 * the upgrade-guide section it comes from. Students arrive with any Gradle from Debian's 4.4.1 to
 * Homebrew's newest 9, and the wrapper pins a 9.x release that cannot be downloaded on the machine
 * that builds ray1, so this list stands in for running those versions: a script line that matches
 * an entry outside a version guard ({@link GradleScriptLines}) would break or warn there.
 */
final class GradleDenylist {
    /** Where in a script an entry applies. */
    enum Where {
        /** Any line. */
        ANYWHERE,
        /** At the project's top level (only inside if/else blocks), where a convention property would be set. */
        TOP_LEVEL,
        /** Inside a task action (doFirst, doLast) or a test listener, which run while the build executes. */
        IN_ACTION
    }

    /** One removed or deprecated construct: a short name, how it is spelled, where it counts, and its source. */
    record Entry(String name, Pattern pattern, Where where, String source, String example) {
        boolean flags(GradleScriptLines.Line line) {
            if (line.guarded()) {
                return false;
            }
            boolean place = switch (where) {
                case ANYWHERE -> true;
                case TOP_LEVEL -> line.topLevel();
                case IN_ACTION -> line.inAction();
            };
            return place && pattern.matcher(line.code()).find();
        }
    }

    /** Properties the scripts set that have no method of the same name, so "name value" is the deprecated space assignment. */
    private static final String ASSIGNED_PROPERTIES = "description|group|enabled|exceptionFormat|showExceptions|showStackTraces"
            + "|showCauses|showStandardStreams|maxHeapSize|minHeapSize|workingDir|ignoreFailures|classpath|testClassesDirs"
            + "|mainClass|executable|maxParallelForks|forkEvery|failFast|encoding|scanForTestClasses|duplicatesStrategy"
            + "|archiveFileName|archiveBaseName|destinationDirectory";

    static final List<Entry> ENTRIES = entries();

    private GradleDenylist() {
    }

    private static List<Entry> entries() {
        List<Entry> list = new ArrayList<>();
        list.add(new Entry("a convention property set at the project's top level",
                Pattern.compile("^\\s*(mainClassName|applicationDefaultJvmArgs|applicationName|sourceCompatibility"
                        + "|targetCompatibility|archivesBaseName|libsDirName|distsDirName|docsDirName|testResultsDirName"
                        + "|testReportDirName)\\s*="),
                Where.TOP_LEVEL, "Upgrading from 8.x to 9.0: the Project conventions are removed (deprecated since 8.2, "
                        + "'Deprecated access to plugin conventions'); set them in application {}, java {} or base {}",
                "applicationDefaultJvmArgs = ['-Xmx1g']"));
        list.add(new Entry("the project read inside a task action",
                Pattern.compile("\\b(project|projectDir|rootDir|rootProject|configurations|sourceSets)\\b|\\b(file|files|fileTree|hasProperty|findProperty|property|relativePath)\\s*\\("),
                Where.IN_ACTION, "Upgrading from 8.x: 'Invocation of Task.project at execution time' is deprecated, "
                        + "an error in Gradle 10; read what the action needs while the build is configured",
                "t.doFirst { t.args = [project.property('x')] }"));
        list.add(new Entry("a property assigned without =",
                Pattern.compile("^\\s*(?:\\w+\\.)*(" + ASSIGNED_PROPERTIES + ")(\\s+(?![=\\-+*/<>!&|?:.}]|in\\b|instanceof\\b)\\S|\\s*\\()"),
                Where.ANYWHERE, "Upgrading from 8.x, Gradle 8.14: the Groovy DSL's space-assignment syntax "
                        + "('propName value', 'propName(value)') is deprecated, an error in Gradle 10",
                "exceptionFormat 'full'"));
        list.add(new Entry("an afterTest/afterSuite/beforeTest/beforeSuite closure",
                Pattern.compile("\\b(afterTest|afterSuite|beforeTest|beforeSuite)\\s*(\\{|\\()"),
                Where.ANYWHERE, "Gradle 9.x API: Test.afterTest(Closure) and its kin are deprecated; "
                        + "Test.addTestListener (since Gradle 1.0) is the lasting spelling",
                "test.afterSuite { suite, result -> }"));
        list.add(new Entry("the compile or runtime configuration",
                Pattern.compile("^\\s*(compile|testCompile|runtime|testRuntime)\\s*(['\"(])"),
                Where.ANYWHERE, "Upgrading from 6.x: the compile and runtime configurations are removed in 7.0; "
                        + "use implementation, runtimeOnly, testImplementation",
                "testCompile 'junit:junit:4.13.2'"));
        list.add(new Entry("the JCenter repository",
                Pattern.compile("\\bjcenter\\s*\\("),
                Where.ANYWHERE, "Upgrading from 7.x: jcenter() is deprecated (JCenter is read-only), removed in 9.0",
                "repositories { jcenter() }"));
        list.add(new Entry("Project.buildDir",
                Pattern.compile("\\bbuildDir\\b"),
                Where.ANYWHERE, "Upgrading from 8.x, Gradle 8.3: Project.buildDir is deprecated; use layout.buildDirectory",
                "def out = new File(buildDir, 'x')"));
        list.add(new Entry("Project.exec or Project.javaexec",
                Pattern.compile("(^|[^.\\w]|\\bproject\\.)(exec|javaexec)\\s*[{(]"),
                Where.ANYWHERE, "Upgrading from 8.x, Gradle 8.11: Project.exec and Project.javaexec are deprecated, "
                        + "removed in 9.0; use an Exec or JavaExec task or providers.exec",
                "javaexec { main = 'x' }"));
        list.add(new Entry("a removed org.gradle.util class",
                Pattern.compile("\\borg\\.gradle\\.util\\.(?!GradleVersion\\b)[A-Z]\\w*"),
                Where.ANYWHERE, "Upgrading from 7.x: the org.gradle.util classes other than GradleVersion are deprecated "
                        + "(7.1) and removed in 9.0 (ConfigureUtil, GUtil, WrapUtil, CollectionUtils, VersionNumber, ...)",
                "import org.gradle.util.ConfigureUtil"));
        list.add(new Entry("an internal Gradle API",
                Pattern.compile("\\borg\\.gradle\\.(api\\.)?internal\\."),
                Where.ANYWHERE, "Gradle's public API: org.gradle.internal and org.gradle.api.internal change "
                        + "without notice between releases",
                "@org.gradle.api.internal.tasks.options.Option(option = 'args')"));
        list.add(new Entry("JavaExec.main",
                Pattern.compile("(^|[^\\w.]|\\w\\.)main\\s*=(?!=)"),
                Where.ANYWHERE, "Upgrading from 7.x: JavaExec.main is deprecated (7.1) and removed in 8.0; "
                        + "use mainClass (6.4 on)",
                "t.main = 'ray.cli.Ray1'"));
        list.add(new Entry("a single classes folder (classesDir, testClassesDir)",
                Pattern.compile("\\b(classesDir|testClassesDir)\\b"),
                Where.ANYWHERE, "Upgrading from 4.x: SourceSetOutput.classesDir and Test.testClassesDir are removed "
                        + "in 5.0; use classesDirs and testClassesDirs",
                "test.testClassesDir = file('x')"));
        list.add(new Entry("an archive or compile task's old output properties",
                Pattern.compile("\\b(archiveName|archivePath|baseName|appendix|classifier|extension|destinationDir)\\s*="),
                Where.ANYWHERE, "Upgrading from 7.x: AbstractArchiveTask's archiveName, baseName, appendix, classifier, "
                        + "extension, destinationDir and JavaCompile.destinationDir are removed in 8.0",
                "jar { archiveName = 'ray1.jar' }"));
        list.add(new Entry("the conventions API",
                Pattern.compile("\\b(convention|getConvention|JavaPluginConvention|ApplicationPluginConvention|BasePluginConvention)\\b"),
                Where.ANYWHERE, "Upgrading from 8.x to 9.0: Project.getConvention() and the *PluginConvention types are removed",
                "project.convention.getPlugin(JavaPluginConvention)"));
        list.add(new Entry("a report's enabled flag",
                Pattern.compile("\\b(html|xml|junitXml|csv)\\.enabled\\b"),
                Where.ANYWHERE, "Upgrading from 7.x: Report.enabled is removed in 8.0; use required",
                "test.reports.html.enabled = false"));
        list.add(new Entry("a build-finished hook or a replaced logger",
                Pattern.compile("\\b(buildFinished|useLogger)\\s*[{(]"),
                Where.ANYWHERE, "Gradle 8.x and 9.x API: Gradle.buildFinished and BuildListener.buildFinished are deprecated "
                        + "(not supported with the configuration cache, which 9 prefers); Gradle.useLogger is deprecated in 9 "
                        + "and removed in 10",
                "gradle.buildFinished { println 'done' }"));
        return List.copyOf(list);
    }
}
