package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import picocli.CommandLine;

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

    /** A sample of Gradescope's export: one student, a group of two, and a zip the metadata does not name. */
    private static Map<ClassSubmission, GradedResult> exportedClass() {
        Map<String, List<Submitter>> metadata = GradescopeMetadata.parse(String.join("\n",
                "submission_1:",
                "  :submitters:",
                "  - :name: Ada Lovelace",
                "    :sid: '101'",
                "    :email: ada@example.edu",
                "  :score: 0.0",
                "submission_2:",
                "  :submitters:",
                "  - :name: \"Turing, Alan\"",
                "    :sid: '103'",
                "    :email: alan@example.edu",
                "  - :name: Kurt Gödel",
                "    :sid: \"0104\"",
                "    :email: kurt@example.edu",
                ""));
        Map<ClassSubmission, GradedResult> graded = new LinkedHashMap<>();
        // Ada: 10 regular points of 10 and 1.5 bonus; the group: 6 of 10 and 1 bonus.
        graded.put(new ClassSubmission("submission_1", Path.of("submission_1"), metadata.get("submission_1")),
                new GradedResult(11.5, 10, Map.of(1, 4.0, 2, 6.0), 1.5, Map.of()));
        graded.put(new ClassSubmission("submission_2", Path.of("submission_2"), metadata.get("submission_2")),
                new GradedResult(7, 10, Map.of(1, 4.0, 2, 2.0), 1, Map.of()));
        graded.put(new ClassSubmission("loose", Path.of("loose.zip"), List.of()), GradedResult.NONE);
        return graded;
    }

    @Test
    public void theGradebookHasEachSubmissionsStudentIds() {
        List<String> rows = Gradebook.csv(exportedClass()).lines().toList();
        assertEquals("id,name,email,SID,Task 1,Task 2,bonus,total", rows.get(0));
        assertEquals("submission_1,Ada Lovelace,ada@example.edu,101,4,6,1.5,11.5", rows.get(1));
        assertEquals("submission_2,\"Turing, Alan; Kurt Gödel\",alan@example.edu; kurt@example.edu,103; 0104,4,2,1,7", rows.get(2));
        assertEquals("loose,,,,0,0,0,0", rows.get(3));
    }

    @Test
    public void lmsCsvHasARowPerStudentByStudentId() {
        Map<ClassSubmission, GradedResult> graded = exportedClass();
        assertEquals("SID,name,email,total\r\n"
                + "101,Ada Lovelace,ada@example.edu,11.5\r\n"
                + "103,\"Turing, Alan\",alan@example.edu,7\r\n"
                + "0104,Kurt Gödel,kurt@example.edu,7\r\n", Gradebook.lms(graded, Gradebook.LmsTotal.score));
        assertEquals("the submission nobody is named for is left out", 1, Gradebook.unnamed(graded));
        assertEquals(List.of("SID,name,email,total", "101,Ada Lovelace,ada@example.edu,10", "103,\"Turing, Alan\",alan@example.edu,7",
                "0104,Kurt Gödel,kurt@example.edu,7"), Gradebook.lms(graded, Gradebook.LmsTotal.capped).lines().toList());
        assertEquals(List.of("SID,name,email,total", "101,Ada Lovelace,ada@example.edu,10", "103,\"Turing, Alan\",alan@example.edu,6",
                "0104,Kurt Gödel,kurt@example.edu,6"), Gradebook.lms(graded, Gradebook.LmsTotal.regular).lines().toList());
    }

    @Test
    public void gradeAllsSwitchChoosesLmsCsvsTotal() {
        GradeAll byDefault = new GradeAll();
        new CommandLine(byDefault).parseArgs("--project", ".", "--classpath", "", "--submissions", ".");
        assertEquals(Gradebook.LmsTotal.score, byDefault.lmsTotal);
        GradeAll regular = new GradeAll();
        new CommandLine(regular).parseArgs("--project", ".", "--classpath", "", "--submissions", ".", "--lms-total", "regular");
        assertEquals(Gradebook.LmsTotal.regular, regular.lmsTotal);
    }

    @Test
    public void gradebookAndReportEscapeWhatTheyShow() {
        Map<ClassSubmission, GradedResult> graded = new LinkedHashMap<>();
        graded.put(new ClassSubmission("s 1", Path.of("s 1"), List.of(new Submitter("<b>Bob</b>, Jr.", "b@x", "1"))),
                new GradedResult(3, 4, Map.of(1, 3.0), 0, Map.of("Task 1: T.easy", true, "Task 1: T.hard", false)));
        graded.put(new ClassSubmission("s2", Path.of("s2.zip"), List.of()), GradedResult.NONE);
        assertEquals("id,name,email,SID,Task 1,bonus,total\r\ns 1,\"<b>Bob</b>, Jr.\",b@x,1,3,0,3\r\ns2,,,,0,0,0\r\n",
                Gradebook.csv(graded));
        String html = ClassReport.html(graded);
        assertTrue(html, html.contains("&lt;b&gt;Bob&lt;/b&gt;, Jr.") && !html.contains("<b>Bob"));
        assertTrue(html, html.contains("<a href=\"s%201/results.json\">s 1</a>"));
        assertTrue("the failed test comes first", html.indexOf("T.hard") < html.indexOf("T.easy"));
    }
}
