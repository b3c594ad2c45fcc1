package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.Test;

/** The class-wide pieces of gradeAll on small hand-written inputs: metadata, results, CSV and HTML (no grading). */
public class ClassReportingTest {
    @Test
    public void readsTheSubmittersOfGradescopesExport() {
        Map<String, List<Submitter>> m = GradescopeMetadata.parse(String.join("\n",
                "# exported",
                "submission_1:",
                "  :submitters:",
                "  - :name: Ada Lovelace",
                "    :sid: '101'",
                "    :email: ada@example.edu",
                "  :created_at: 2024-01-01 10:00:00.000000000 -08:00",
                "  :history:",
                "  - :submitters:",
                "    - :name: Someone Else",
                "submission_2:",
                "  :score: 3.0",
                "  :submitters:",
                "    - :name: \"O'Neil, \\\"Pat\\\"\"",
                "      :email: pat@example.edu",
                "    - :name: 'Lee ''Sam'''",
                "\"submission_3\":",
                "  :submitters: []"));
        assertEquals(List.of(new Submitter("Ada Lovelace", "ada@example.edu", "101")), m.get("submission_1"));
        assertEquals(List.of(new Submitter("O'Neil, \"Pat\"", "pat@example.edu", ""), new Submitter("Lee 'Sam'", "", "")),
                m.get("submission_2"));
        assertEquals(List.of(), m.get("submission_3"));
    }

    @Test
    public void quotesCsvFieldsOnlyWhenNeeded() {
        assertEquals("a,\"b, c\",\"say \"\"hi\"\"\",\"two\nlines\",1.5\r\n",
                Csv.row(List.of("a", "b, c", "say \"hi\"", "two\nlines", "1.5")));
    }

    @Test
    public void sumsRegularPointsPerTaskAndBonusApart() {
        GradedResult r = GradedResult.parse("{\"score\": 7.5, \"max_score\": 10, \"tests\": ["
                + "{\"name\": \"a\", \"score\": 2, \"max_score\": 2, \"status\": \"passed\", \"tags\": [\"task1\"]},"
                + "{\"name\": \"b\", \"score\": 4.5, \"max_score\": 6, \"status\": \"failed\", \"tags\": [\"task2\"]},"
                + "{\"name\": \"c\", \"score\": 1, \"max_score\": 0, \"status\": \"passed\", \"tags\": [\"task2\", \"bonus\"]}]}");
        assertEquals(Map.of(1, 2.0, 2, 4.5), r.taskPoints());
        assertEquals(1, r.bonus(), 0);
        assertEquals(Map.of("a", true, "b", false, "c", true), r.passed());
        assertEquals(GradedResult.NONE, GradedResult.parse("not json at all".substring(0, 0)));
        assertEquals("a file written before the maximum moved to extra_data", 10, r.maxScore(), 0);
    }

    @Test
    public void readsTheMaximumFromExtraData() {
        String json = GradescopeResults.json(GradescopeResults.of(GradescopeResultsTest.OUTCOMES, "", 1.0));
        GradedResult r = GradedResult.parse(json);
        assertEquals(10, r.maxScore(), 0);
        assertEquals(6.5, r.score(), 0);
        assertEquals(1.5, r.bonus(), 0);
    }

    @Test
    public void gradebookAndReportEscapeWhatTheyShow() {
        Map<ClassSubmission, GradedResult> graded = new LinkedHashMap<>();
        graded.put(new ClassSubmission("s 1", Path.of("s 1"), List.of(new Submitter("<b>Bob</b>, Jr.", "b@x", "1"))),
                new GradedResult(3, 4, Map.of(1, 3.0), 0, Map.of("Task 1: T.easy", true, "Task 1: T.hard", false)));
        graded.put(new ClassSubmission("s2", Path.of("s2.zip"), List.of()), GradedResult.NONE);
        assertEquals("id,name,email,Task 1,bonus,total\r\ns 1,\"<b>Bob</b>, Jr.\",b@x,3,0,3\r\ns2,,,0,0,0\r\n", Gradebook.csv(graded));
        String html = ClassReport.html(graded);
        assertTrue(html, html.contains("&lt;b&gt;Bob&lt;/b&gt;, Jr.") && !html.contains("<b>Bob"));
        assertTrue(html, html.contains("<a href=\"s%201/results.json\">s 1</a>"));
        assertTrue("the failed test comes first", html.indexOf("T.hard") < html.indexOf("T.easy"));
    }
}
