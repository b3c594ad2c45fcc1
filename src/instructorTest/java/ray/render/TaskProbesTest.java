package ray.render;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static org.junit.Assume.assumeTrue;

import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import org.junit.AfterClass;
import org.junit.Before;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;
import org.junit.rules.TemporaryFolder;
import ray.assignment.Assignment;
import ray.render.TaskProbes.Part;
import ray.testing.StudentTask;
import ray.variants.StubBuild;

/**
 * {@link TaskProbes}: the solution is never called a stub, the handout's stub of each student file
 * is found (and nothing else), code that throws or takes too long is no stub, and the line
 * {@code ray1 render} ends with says which tasks are stubs and where to start.
 */
@RunWith(Parameterized.class)
public class TaskProbesTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    /** Each student file's handout stub, compiled alone into a class folder of its own. */
    private static final Map<Part, Path> STUB_CLASSES = new java.util.EnumMap<>(Part.class);

    /** The presets that together choose every task of the table: each part is the students' under one of them. */
    @Parameters(name = "{0}")
    public static List<Object[]> presets() {
        return List.of(new Object[] {"course-2017"}, new Object[] {"course-2019"}, new Object[] {"course-2019-part2"});
    }

    private static Assignment before;
    /** The preset this run's tests probe under. */
    private final String preset;

    public TaskProbesTest(String preset) {
        this.preset = preset;
    }

    @BeforeClass
    public static void compileTheStubs() throws Exception {
        before = Assignment.current();
        for (Part part : Part.values()) {
            STUB_CLASSES.put(part, StubBuild.compile(Map.of(part.file, StubBuild.stubOf(part.file)),
                    FOLDER.getRoot().toPath().resolve("stub-" + part.className)));
        }
    }

    /** The preset of the test running now, for the child loaders' assignment. */
    private static String runPreset;

    @Before
    public void useThePreset() {
        runPreset = preset;
        Assignment.use(Assignment.preset(preset));
    }

    @AfterClass
    public static void restoreTheAssignment() {
        Assignment.use(before);
    }

    /** The parts that are the students' under this run's preset. */
    private static List<Part> studentsParts() {
        return Arrays.stream(Part.values()).filter(Part::isStudents).collect(Collectors.toList());
    }

    @Test
    public void theSolutionIsNoStubAndPassesEveryProbe() {
        for (Part part : Part.values()) {
            TaskProbes.Finding finding = TaskProbes.probe(part);
            assertFalse(part + ": " + finding, finding.stub);
            assertNull(part + ": " + finding, finding.problem);
        }
        assertEquals(EnumSet.noneOf(Part.class), TaskProbes.stubs());
        assertNull(TaskProbes.stillStubsLine(EnumSet.noneOf(Part.class)));
    }

    /** The parts are the students' files, task by task, as the table of tasks lists them. */
    @Test
    public void thePartsAreTheStudentFiles() {
        for (StudentTask task : StudentTask.values()) {
            List<String> files = Arrays.stream(Part.values()).filter(p -> p.task() == task.number).map(p -> p.file)
                    .collect(Collectors.toList());
            assertEquals(task.label(), task.files, files);
        }
        assertEquals(studentsParts().size(), StudentTask.values().stream().mapToInt(t -> t.files.size()).sum());
        for (Part part : Part.values()) {
            assertTrue(part.file, part.file.endsWith("/" + part.className + ".java"));
            assertTrue(part + " is the students' under one of the presets", presets().stream()
                    .anyMatch(p -> Assignment.preset((String) p[0]).number(part.taskId) > 0));
        }
    }

    @Test
    public void eachStubIsFoundAndNothingElse() throws Exception {
        for (Part part : studentsParts()) {
            assertEquals("with the stub of " + part.file, Set.of(part.name()), stubsWith(List.of(STUB_CLASSES.get(part))));
        }
    }

    @Test
    public void aTasksStubsTogetherAndTheWholeHandout() throws Exception {
        for (StudentTask task : StudentTask.values()) {
            List<Path> folders = new ArrayList<>();
            Set<String> expected = new TreeSet<>();
            for (Part part : Part.values()) {
                if (part.task() == task.number) {
                    folders.add(STUB_CLASSES.get(part));
                    expected.add(part.name());
                }
            }
            assertEquals(task.label(), expected, stubsWith(folders));
            // The line the render ends with names exactly this task.
            String line = lineWith(folders);
            assertEquals(line, TaskProbes.stillStubsLine(partsNamed(expected)), line);
            String named = line.substring(0, line.indexOf(". "));
            for (StudentTask other : StudentTask.values()) {
                assertEquals(line, other.equals(task), named.contains("Task " + other.number + " ("));
            }
        }
        // Every stub at once (a part the preset does not give students is solved, and never probed).
        Set<String> all = studentsParts().stream().map(Part::name).collect(Collectors.toCollection(TreeSet::new));
        assertEquals(all, stubsWith(new ArrayList<>(STUB_CLASSES.values())));
    }

    /** Code that throws is written (only broken), and code that does not answer in time is not known to be a stub. */
    @Test
    public void codeThatThrowsOrTakesTooLongIsNoStub() throws Exception {
        Path throwing = StubBuild.compile(Map.of(
                Part.SPHERE.file, replace(Part.SPHERE, "return false;", "throw new IllegalStateException(\"unfinished\");"),
                Part.REPEAT_TEXTURE.file, replace(Part.REPEAT_TEXTURE, "return Vec3.ZERO;", "return null;"),
                Part.PERSPECTIVE_CAMERA.file, replace(Part.PERSPECTIVE_CAMERA, "return new Ray(viewPoint, w.negate(), 0, 0);",
                        "throw new StackOverflowError();"),
                // Answers as the stub does, but only after a minute.
                Part.GROUP.file, replace(Part.GROUP, "return false;",
                        "try { Thread.sleep(60_000); } catch (InterruptedException e) { } return false;")),
                FOLDER.getRoot().toPath().resolve("throwing"));
        long began = System.nanoTime();
        Set<String> stubs = stubsWith(List.of(throwing), 300);
        long millis = (System.nanoTime() - began) / 1_000_000;
        assertEquals(Set.of(), stubs);
        // Not waiting for the group's minute: the probes give up at their limit (300 ms each); the
        // bound is generous, for a loaded machine.
        assertTrue("the probes took " + millis + " ms", millis < 30_000);
        try (URLClassLoader loader = StubBuild.loader(List.of(throwing))) {
            Object finding = probe(loader, "SPHERE");
            assertEquals("it throws java.lang.IllegalStateException: unfinished", finding.getClass().getField("problem").get(finding));
            assertEquals(false, finding.getClass().getField("stub").get(finding));
        }
    }

    /**
     * A tree whose build is written (one leaf over everything, which the framework refuses) and whose
     * searches are still the stub's is no stub: the probe names the build's broken rule.
     */
    @Test
    public void aTreeWithABrokenBuildIsNoStub() throws Exception {
        Path halfDone = StubBuild.compile(Map.of(Part.BVH_TREE.file,
                replace(Part.BVH_TREE, "return null;", "return BvhNode.leaf(boxOf(start, end), start, end);")),
                FOLDER.getRoot().toPath().resolve("half-done-tree"));
        try (URLClassLoader loader = StubBuild.loader(List.of(halfDone))) {
            Object finding = probe(loader, "BVH_TREE");
            assertEquals(false, finding.getClass().getField("stub").get(finding));
            String problem = (String) finding.getClass().getField("problem").get(finding);
            assertTrue(problem, problem.startsWith("over six plates one behind another, BvhTree.build over 6 primitives: "));
        }
    }

    private static String replace(Part part, String stub, String instead) throws Exception {
        String source = StubBuild.stubOf(part.file);
        assertTrue(part.file + " has no '" + stub + "'", source.contains(stub));
        return source.replace(stub, instead);
    }

    @Test
    public void theLineNamesTheStubsAndWhereToStart() {
        for (Part part : studentsParts()) {
            String line = TaskProbes.stillStubsLine(EnumSet.of(part));
            assertTrue(line, line.contains(part.file) && line.contains("TODO(Task " + part.task() + ")"));
            assertTrue(line, line.chars().allMatch(c -> c >= ' ' && c < 127));
        }
        if (preset.equals("course-2019-part2")) {
            // The tree's two files, one task: both still stubs name the task.
            assertEquals("Still stubs: Task 1 (Bounding volume hierarchy). Start with Task 1: the TODO(Task 1) comments in"
                    + " src/main/java/ray/bvh/BoundingBoxes.java and BvhTree.java (see docs/assignment.md).",
                    TaskProbes.stillStubsLine(EnumSet.of(Part.BOUNDING_BOXES, Part.BVH_TREE)));
        }
        assumeTrue("the lines below number the tasks as course-2017 does", preset.equals("course-2017"));
        // Numbered as course-2017 numbers them: cameras, ray color, group, sphere, lighting, triangle, textures, cylinder.
        assertEquals("Still stubs: Task 1 (Camera rays), Task 2 (Ray color), Task 3 (Group), Task 4 (Sphere), Task 5 (Lighting),"
                + " Task 6 (Triangle), Task 7 (Textures), Task 8 (Cylinder, extra credit). Start with Task 1: the TODO(Task 1) comments in"
                + " src/main/java/ray/camera/PerspectiveCamera.java and OrthographicCamera.java (see docs/assignment.md).",
                TaskProbes.stillStubsLine(EnumSet.copyOf(studentsParts())));
        // After the cameras, the table of tasks' order (pictures earliest) puts the ray's color, then the group.
        assertEquals("Still stubs: Task 2 (Ray color), Task 3 (Group), Task 4 (Sphere), Task 6 (Triangle). Start with Task 2: the"
                + " TODO(Task 2) comment in src/main/java/ray/render/RayTracer.java (see docs/assignment.md).",
                TaskProbes.stillStubsLine(EnumSet.of(Part.RAY_TRACER, Part.SPHERE, Part.TRIANGLE, Part.GROUP)));
        assertEquals("Still stubs: Task 3 (Group), Task 4 (Sphere), Task 6 (Triangle). Start with Task 3: the TODO(Task 3) comment in"
                + " src/main/java/ray/surface/Group.java (see docs/assignment.md).",
                TaskProbes.stillStubsLine(EnumSet.of(Part.SPHERE, Part.TRIANGLE, Part.GROUP)));
        // Half a task is named by its file.
        assertEquals("Still stubs: Task 1 (OrthographicCamera), Task 5 (Phong), Task 7 (ClampTexture). Start with Task 1: the TODO(Task 1)"
                + " comment in src/main/java/ray/camera/OrthographicCamera.java (see docs/assignment.md).",
                TaskProbes.stillStubsLine(EnumSet.of(Part.ORTHOGRAPHIC_CAMERA, Part.PHONG, Part.CLAMP_TEXTURE)));
        // The light loops come after the sphere: without them every picture is black.
        assertEquals("Still stubs: Task 5 (Lighting), Task 7 (Textures), Task 8 (Cylinder, extra credit). Start with Task 5: the TODO(Task 5)"
                + " comments in src/main/java/ray/shading/Lambertian.java and Phong.java (see docs/assignment.md).",
                TaskProbes.stillStubsLine(EnumSet.of(Part.LAMBERTIAN, Part.PHONG, Part.REPEAT_TEXTURE, Part.CLAMP_TEXTURE, Part.CYLINDER)));
        // The extra credit alone is offered, not prescribed.
        assertEquals("Still a stub: Task 8 (Cylinder, extra credit). For the extra credit: the TODO(Task 8) comment in"
                + " src/main/java/ray/surface/Cylinder.java (see docs/assignment.md).",
                TaskProbes.stillStubsLine(EnumSet.of(Part.CYLINDER)));
    }

    /** The names of the parts that {@link TaskProbes#stubs()} finds with {@code folders}' classes in place of the solution's. */
    private static Set<String> stubsWith(List<Path> folders) throws Exception {
        return stubsWith(folders, TaskProbes.DEFAULT_LIMIT_MILLIS);
    }

    private static Set<String> stubsWith(List<Path> folders, long limitMillis) throws Exception {
        try (URLClassLoader loader = StubBuild.loader(folders)) {
            Class<?> probes = probesUnderEveryTask(loader);
            assertFalse("the loader gave this JVM's TaskProbes", probes == TaskProbes.class);
            Set<?> stubs = (Set<?>) probes.getMethod("stubs", long.class).invoke(null, limitMillis);
            return stubs.stream().map(p -> ((Enum<?>) p).name()).collect(Collectors.toCollection(TreeSet::new));
        }
    }

    /** The line {@code ray1 render} ends with when {@code folders}' classes replace the solution's, or null. */
    private static String lineWith(List<Path> folders) throws Exception {
        try (URLClassLoader loader = StubBuild.loader(folders)) {
            Class<?> probes = probesUnderEveryTask(loader);
            Object stubs = probes.getMethod("stubs").invoke(null);
            return (String) probes.getMethod("stillStubsLine", Set.class).invoke(null, stubs);
        }
    }

    /** The loader's TaskProbes, its assignment set to this JVM's (the run's preset). */
    private static Class<?> probesUnderEveryTask(URLClassLoader loader) throws Exception {
        Class<?> assignment = loader.loadClass(Assignment.class.getName());
        assignment.getMethod("use", assignment).invoke(null, assignment.getMethod("preset", String.class).invoke(null, runPreset));
        return loader.loadClass(TaskProbes.class.getName());
    }

    private static Set<Part> partsNamed(Set<String> names) {
        Set<Part> parts = EnumSet.noneOf(Part.class);
        names.forEach(name -> parts.add(Part.valueOf(name)));
        return parts;
    }

    private static Object probe(URLClassLoader loader, String part) throws Exception {
        Class<?> probes = probesUnderEveryTask(loader);
        Class<?> parts = loader.loadClass(Part.class.getName());
        Object value = Arrays.stream(parts.getEnumConstants()).filter(p -> ((Enum<?>) p).name().equals(part)).findFirst().orElseThrow();
        return probes.getMethod("probe", parts).invoke(null, value);
    }
}
