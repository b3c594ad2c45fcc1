package ray.grading;

import java.io.IOException;
import java.nio.file.Path;
import picocli.CommandLine.Option;
import ray.assignment.Assignment;

/** The options that say which assignment a grade is of (gradle's -Passignment, -Ptasks and -Phints), shared by the grading commands. */
public final class AssignmentOptions {
    @Option(names = "--assignment", description = "Grade this assignment: a preset's name or an assignment file (default: the project's"
            + " assignment.properties).")
    String given;

    @Option(names = "--tasks", description = "The tasks of the assignment for this grade, by id, in order (overrides the assignment's).")
    String tasks;

    @Option(names = "--hints", description = "The hint level of the failure messages: goal, steps or formulas (overrides the assignment's).")
    String hints;

    /** The assignment these options name, against {@code project}'s own file. */
    Assignment resolve(Path project) throws IOException {
        return Assignment.resolve(project, given, Assignment.overrides(tasks, hints));
    }
}
