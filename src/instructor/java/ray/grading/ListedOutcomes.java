package ray.grading;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Only the instructor's list of tests decides points: what a run reported is matched against it by
 * test id. Each listed test appears once, worth what the list says (whatever the report claims), and
 * passes only when it was reported exactly once and passed; a listed test reported never or more than
 * once fails, saying so; a reported test the list does not hold counts for nothing.
 */
final class ListedOutcomes {
    private ListedOutcomes() {
    }

    /** The listed tests, in the list's order, each with the result reported for it. */
    static List<TestOutcome> judged(List<TestOutcome> listed, List<TestOutcome> reported) {
        Map<String, List<TestOutcome>> byId = new LinkedHashMap<>();
        for (TestOutcome t : reported) {
            byId.computeIfAbsent(t.id(), k -> new ArrayList<>()).add(t);
        }
        List<TestOutcome> judged = new ArrayList<>();
        for (TestOutcome expected : listed) {
            List<TestOutcome> reports = byId.getOrDefault(expected.id(), List.of());
            if (reports.size() == 1) {
                judged.add(expected.withResultOf(reports.get(0)));
            } else {
                judged.add(expected.failedWith(reports.isEmpty() ? "this test reported no result"
                        : "this test reported " + reports.size() + " results"));
            }
        }
        return judged;
    }
}
