package ray.tools;

import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import ray.assignment.Assignment;
import ray.assignment.AssignmentException;

/**
 * The assignment an instructor's tool (the handout, the grading packages) is run for, from its
 * arguments {@code --assignment PRESET|FILE}, {@code --tasks ID,…} and {@code --hints LEVEL} (as the
 * gradle tasks pass -Passignment, -Ptasks and -Phints; any before {@code --classes}), else the
 * project's assignment file.
 */
final class AssignmentArguments {
    private AssignmentArguments() {
    }

    /**
     * Makes that assignment this process's ({@link Assignment#use}) and returns it; a bad one ends
     * the process with its one-line error.
     */
    static Assignment use(Path project, String[] args) throws IOException {
        String given = null;
        Map<String, String> overrides = new LinkedHashMap<>();
        for (int i = 0; i + 1 < args.length && !args[i].equals("--classes"); i++) {
            switch (args[i]) {
                case "--assignment":
                    given = args[i + 1];
                    break;
                case "--tasks":
                    overrides.put("tasks", args[i + 1]);
                    break;
                case "--hints":
                    overrides.put("hints", args[i + 1]);
                    break;
                default:
                    break;
            }
        }
        try {
            Assignment assignment = Assignment.resolve(project, given, overrides);
            Assignment.use(assignment);
            return assignment;
        } catch (AssignmentException e) {
            System.err.println("error: " + e.getMessage());
            System.exit(2);
            return null;
        }
    }
}
