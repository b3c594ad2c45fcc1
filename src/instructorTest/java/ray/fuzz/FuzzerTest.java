package ray.fuzz;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.scene.SceneException;

/**
 * The short fuzz run of {@code gradle test} (the long one is {@code gradle fuzz}), and checks that
 * the fuzzer really damages files and really tells a clean error from a bad one.
 */
public class FuzzerTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    /** Not the long run's seed, so that the two runs cover different cases. */
    private static final long SEED = 20261122;
    private static final int CASES = 5000;

    @Test(timeout = 300_000)
    public void shortRunOverTheShippedScenesEndsEveryCaseInARenderOrACleanError() throws Exception {
        Path work = FOLDER.newFolder("short").toPath();
        FuzzSummary summary = new Fuzzer(Corpus.of(Path.of("scenes")), work, SEED, 2, null).run(CASES);
        assertEquals(summary.markdown(), CASES, summary.done());
        assertEquals(String.join("\n", summary.failures()), 0, summary.failed());
        // Both ends are reached often: the mutations neither always break the scene nor never do.
        assertTrue(summary.markdown(), summary.count(Outcome.Kind.RENDERED) > CASES / 5);
        assertTrue(summary.markdown(), summary.count(Outcome.Kind.ERROR) > CASES / 5);
        for (String row : new String[] {"scene: BYTE_FLIP", "scene: ELEMENT_DELETE", "scene: ELEMENT_DUPLICATE",
                "scene: ATTRIBUTE_DELETE", "scene: ATTRIBUTE_DUPLICATE", "scene: NUMBER", "mesh: BYTE_FLIP", "mesh: NUMBER",
                "mesh: LINE_DELETE", "mesh: LINE_DUPLICATE"}) {
            long[] r = summary.row(row);
            assertTrue(row + " ran", r[0] + r[1] + r[2] > 20);
        }
    }

    /** The fuzzer's own net: a case that hangs or whose runner throws is a failure, and the run still ends. */
    @Test(timeout = 60_000)
    public void aHangingOrCrashingCaseIsAFailureAndTheRunEnds() throws Exception {
        Path work = FOLDER.newFolder("net").toPath();
        FuzzSummary summary = new Fuzzer(Corpus.of(Path.of("scenes")), work, SEED, 2, null, folder -> (c, damaged) -> {
            if (c.index == 3) {
                // Hangs until the fuzzer gives up and interrupts it (so that no thread spins on after the test).
                while (!Thread.currentThread().isInterrupted()) {
                    Thread.onSpinWait();
                }
                return Outcome.rendered(0, 1);
            }
            if (c.index == 4) {
                throw new IllegalStateException("a runner bug");
            }
            return Outcome.rendered(0, 1);
        }, 1).run(40);
        assertEquals(2, summary.failed());
        List<String> failures = summary.failures();
        assertTrue(failures.toString(), failures.stream().anyMatch(f -> f.startsWith("case 3: ") && f.endsWith(": no result after 1 s (a hang)")));
        assertTrue(failures.toString(), failures.stream().anyMatch(f -> f.startsWith("case 4: ")
                && f.contains(": the case runner threw java.lang.IllegalStateException: a runner bug")));
        // Case 3's worker (odd cases) stopped there; the other ran all its 20 cases.
        assertEquals(2 + 20, summary.done());
        assertTrue(summary.markdown(), summary.markdown().contains("worker 1 stopped at case 3 (a hang)"));
    }

    @Test
    public void aCaseIsTheSameForTheSameSeedAndIndexAndDiffersForAnother() {
        Corpus corpus = Corpus.of(Path.of("scenes"));
        for (long i = 0; i < 50; i++) {
            FuzzCase a = FuzzCase.of(corpus, SEED, i);
            FuzzCase b = FuzzCase.of(corpus, SEED, i);
            assertEquals(a.toString(), b.toString());
            assertArrayEquals(CaseRunner.damaged(corpus, a), CaseRunner.damaged(corpus, b));
        }
        long differing = 0;
        for (long i = 0; i < 50; i++) {
            differing += FuzzCase.of(corpus, SEED, i).toString().equals(FuzzCase.of(corpus, SEED + 1, i).toString()) ? 0 : 1;
        }
        assertTrue(differing > 40);
    }

    @Test
    public void theCorpusIsEveryShippedSceneWithItsMeshesAndTexturesAndNoReferenceRender() {
        Corpus corpus = Corpus.of(Path.of("scenes"));
        assertEquals(25, corpus.scenes.size());
        assertEquals(java.util.List.of(Path.of("meshes/torus-flat.obj")), corpus.meshes.get(Path.of("mesh-flat.xml")));
        assertEquals(java.util.List.of(Path.of("meshes/vase.obj"), Path.of("meshes/torus-smooth.obj"), Path.of("meshes/torus-flat.obj")),
                corpus.meshes.get(Path.of("meshes-and-boxes.xml")));
        assertEquals(java.util.List.of(Path.of("meshes/icosphere-room.obj")),
                corpus.meshes.get(Path.of("hard/inside-closed-mesh.xml")));
        assertTrue(corpus.meshes.get(Path.of("one-sphere.xml")).isEmpty());
        assertTrue("the image size is not a texture", corpus.textures.get(Path.of("one-sphere.xml")).isEmpty());
        assertEquals(java.util.List.of(Path.of("textures/globe.png"), Path.of("textures/moon.png")),
                corpus.textures.get(Path.of("textured/eclipse.xml")));
        assertEquals(java.util.List.of(Path.of("meshes/tablecloth.obj"), Path.of("meshes/vase.obj")),
                corpus.meshes.get(Path.of("textured/tablecloth.xml")));
    }

    /**
     * A generator per seed. java.util.Random's first numbers from neighbouring seeds are alike (its
     * seed only scrambles the low bits), so the seeds are spread first, as FuzzCase's are.
     */
    private static java.util.Random random(int seed) {
        return new java.util.Random(seed * 0x9E3779B97F4A7C15L);
    }

    @Test
    public void elementMutationsRemoveOrRepeatOneWholeElement() {
        String xml = "<a><b>1</b><c x=\"2\"/></a>";
        java.util.Set<String> deleted = new java.util.HashSet<>();
        java.util.Set<String> duplicated = new java.util.HashSet<>();
        for (int seed = 0; seed < 40; seed++) {
            deleted.add(Mutation.ELEMENT_DELETE.apply(xml, random(seed)));
            duplicated.add(Mutation.ELEMENT_DUPLICATE.apply(xml, random(seed)));
        }
        assertEquals(java.util.Set.of("", "<a><c x=\"2\"/></a>", "<a><b>1</b></a>"), deleted);
        assertEquals(java.util.Set.of("<a><b>1</b><c x=\"2\"/></a><a><b>1</b><c x=\"2\"/></a>",
                "<a><b>1</b><b>1</b><c x=\"2\"/></a>", "<a><b>1</b><c x=\"2\"/><c x=\"2\"/></a>"), duplicated);
    }

    @Test
    public void attributeMutationsRemoveOrRepeatOneAttribute() {
        String xml = "<s type=\"A\" name=\"n\"><t/></s>";
        java.util.Set<String> deleted = new java.util.HashSet<>();
        java.util.Set<String> duplicated = new java.util.HashSet<>();
        for (int seed = 0; seed < 60; seed++) {
            deleted.add(Mutation.ATTRIBUTE_DELETE.apply(xml, random(seed)));
            duplicated.add(Mutation.ATTRIBUTE_DUPLICATE.apply(xml, random(seed)));
        }
        assertEquals(java.util.Set.of("<s name=\"n\"><t/></s>", "<s type=\"A\"><t/></s>"), deleted);
        // In its own tag (twice the same attribute: not XML), or in either start tag, after the tag's name.
        assertEquals(java.util.Set.of("<s type=\"A\" type=\"A\" name=\"n\"><t/></s>", "<s type=\"A\" name=\"n\" name=\"n\"><t/></s>",
                "<s type=\"A\" name=\"n\"><t type=\"A\"/></s>",
                "<s name=\"n\" type=\"A\" name=\"n\"><t/></s>", "<s type=\"A\" name=\"n\"><t name=\"n\"/></s>"), duplicated);
    }

    @Test
    public void numberMutationReplacesOneNumberAndNothingElse() {
        String xml = "<radius>2.5</radius><center>1 2 3</center>";
        java.util.List<Markup.Span> numbers = Markup.numbers(xml);
        assertEquals(4, numbers.size());
        for (int seed = 0; seed < 100; seed++) {
            String mutated = Mutation.NUMBER.apply(xml, random(seed));
            boolean oneReplaced = numbers.stream().anyMatch(n -> mutated.startsWith(xml.substring(0, n.start))
                    && mutated.endsWith(xml.substring(n.end)));
            assertTrue(mutated, oneReplaced);
        }
    }

    @Test
    public void byteFlipsChangeAtMostFourBytesAndLeaveTheOriginalAlone() {
        byte[] original = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".getBytes(StandardCharsets.UTF_8);
        byte[] copy = original.clone();
        for (int seed = 0; seed < 100; seed++) {
            byte[] damaged = Mutation.BYTE_FLIP.apply(original, random(seed));
            assertTrue(Math.abs(damaged.length - original.length) <= 4);
            assertArrayEquals("the original is not written to", copy, original);
        }
    }

    @Test
    public void lineMutationsRemoveOrRepeatOneLine() {
        String obj = "v 0 0 0\nf 1 1 1\n";
        java.util.Set<String> results = new java.util.HashSet<>();
        for (int seed = 0; seed < 40; seed++) {
            results.add(Mutation.LINE_DELETE.apply(obj, random(seed)));
            results.add(Mutation.LINE_DUPLICATE.apply(obj, random(seed)));
        }
        assertEquals(java.util.Set.of("f 1 1 1\n", "v 0 0 0\n", "v 0 0 0\nv 0 0 0\nf 1 1 1\n", "v 0 0 0\nf 1 1 1\nf 1 1 1\n"),
                results);
    }

    @Test
    public void theOracleRejectsErrorsThatBreakTheFormat() throws Exception {
        Path scene = FOLDER.newFile("three-lines.xml").toPath();
        Files.writeString(scene, "<scene>\n</scene>\n");
        assertNull(ErrorFormat.problemWith(new SceneException(scene, 2, 1, "no camera; expected one"), scene));
        assertEquals("line 4 is past the end of the file",
                ErrorFormat.problemWith(new SceneException(scene, 4, 1, "oops; expected"), scene));
        assertEquals("does not say what was expected",
                ErrorFormat.problemWith(new SceneException(scene, 1, 1, "oops"), scene));
        assertEquals("names neither the scene nor an existing file",
                ErrorFormat.problemWith(new SceneException(scene.resolveSibling("nope.obj"), 1, 1, "x; expected y"), scene));
        SceneException twoLines = new SceneException(scene, 1, 1, "one\ntwo; expected") {
            @Override
            public String getMessage() {
                return "a\nb";
            }
        };
        assertEquals("more than one line", ErrorFormat.problemWith(twoLines, scene));
    }
}
