package ray.grading;

import com.google.gson.Gson;
import com.google.gson.JsonParseException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * What a student reads of a grading: each failed test's name and output, from results.json, its
 * HTML pages turned back into text (Gradescope shows a render test's page as HTML).
 */
record GradedFeedback(List<Failed> failed) {
    /** One failed test: its name as results.json gives it, its output as text, and whether it is a bonus test. */
    record Failed(String name, String output, boolean bonus) {
        /**
         * Whether it is a whole-scene render test (Gradescope names it "Task N (…): SphereRenderTest.rendersLikeTheReference[…]")
         * that rendered a picture unlike the reference (not one whose code threw before there was a picture).
         */
        boolean isDifferingRender() {
            return name.matches(".*Render(Bonus)?Test\\..*") && output.contains(" does not look like ");
        }
    }

    @SuppressWarnings("unchecked")
    static GradedFeedback read(Path resultsJson) throws IOException {
        Map<String, Object> results;
        try {
            results = new Gson().fromJson(Files.readString(resultsJson, StandardCharsets.UTF_8), Map.class);
        } catch (JsonParseException e) {
            throw new IOException(resultsJson + " is not JSON: " + e.getMessage(), e);
        }
        List<Failed> failed = new ArrayList<>();
        for (Map<String, Object> test : (List<Map<String, Object>>) results.getOrDefault("tests", List.of())) {
            if (!"passed".equals(test.get("status"))) {
                List<String> tags = (List<String>) test.getOrDefault("tags", List.of());
                failed.add(new Failed(String.valueOf(test.get("name")), text(String.valueOf(test.getOrDefault("output", ""))),
                        tags.contains("bonus")));
            }
        }
        return new GradedFeedback(failed);
    }

    /** The page's text: its escapes undone (the tags stay; a mistake's name is never split by one). */
    static String text(String html) {
        return html.replace("&#39;", "'").replace("&quot;", "\"").replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&");
    }
}
