package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.Test;

/** What a submission's own text can make of the results file: cut messages and a file under 1 MB. */
@SuppressWarnings("unchecked")
public class OutputLimitsTest {
    private static TestOutcome failed(int n, String message) {
        return new TestOutcome("ray.surface.SphereTest#t" + n, "ray.surface.SphereTest", "t" + n, 2, "Sphere", 1, false, "visible",
                false, message, 0);
    }

    @Test
    public void textIsCutAtTheLimitWithAMarkAndNeverInsideACharacter() {
        assertEquals("short", OutputLimits.cut("short", 10));
        assertEquals("0123456789" + OutputLimits.CUT, OutputLimits.cut("0123456789abc", 10));
        // "😀" is two chars; a cut between them would leave half a character in the JSON.
        String emoji = "012345678\uD83D\uDE00";
        assertEquals("012345678" + OutputLimits.CUT, OutputLimits.cut(emoji, 10));
    }

    @Test
    public void messagesAreCutAndPassingTestsKeepTheirStatus() {
        List<TestOutcome> cut = OutputLimits.cutMessages(List.of(failed(1, "x".repeat(10_000)), failed(2, "fine")), 4_000);
        assertEquals(4_000 + OutputLimits.CUT.length(), cut.get(0).message().length());
        assertEquals("fine", cut.get(1).message());
        assertTrue(!cut.get(0).passed());
    }

    /** A builder as the grader's: every message in the file, pictures as a 20 kB blob per test when allowed. */
    private static Map<String, Object> build(List<TestOutcome> outcomes, String output, boolean pictures) {
        List<Map<String, Object>> tests = new ArrayList<>();
        for (TestOutcome t : outcomes) {
            Map<String, Object> test = new LinkedHashMap<>();
            test.put("output", t.message() + (pictures ? "p".repeat(20_000) : ""));
            tests.add(test);
        }
        Map<String, Object> results = new LinkedHashMap<>();
        results.put("output", output);
        results.put("tests", tests);
        return results;
    }

    @Test
    public void theFileStaysUnderOneMegabyteWhateverTheSubmissionSays() {
        List<TestOutcome> loud = new ArrayList<>();
        for (int n = 0; n < 300; n++) {
            loud.add(failed(n, "payload ".repeat(100_000)));
        }
        Map<String, Object> results = OutputLimits.within(loud, "out".repeat(1_000_000), OutputLimitsTest::build);
        int bytes = OutputLimits.bytes(results);
        assertTrue(bytes + " bytes", bytes <= OutputLimits.RESULTS_BYTES);
        String first = (String) ((List<Map<String, Object>>) results.get("tests")).get(0).get("output");
        assertTrue(first, first.endsWith(OutputLimits.CUT) && !first.contains("ppp"));
    }

    @Test
    public void aQuietSubmissionKeepsItsPictures() {
        List<TestOutcome> few = List.of(failed(1, "expected:<1> but was:<2>"), failed(2, "no hit"));
        Map<String, Object> results = OutputLimits.within(few, "Graded files: Sphere.java", OutputLimitsTest::build);
        String first = (String) ((List<Map<String, Object>>) results.get("tests")).get(0).get("output");
        assertTrue(first.startsWith("expected:<1> but was:<2>ppp"));
    }
}
