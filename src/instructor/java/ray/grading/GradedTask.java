package ray.grading;

import java.util.Optional;
import ray.assignment.Assignment;
import ray.assignment.Task;

/**
 * The task a graded test counts toward, as the grader reads it: the table of tasks gives a test
 * class its task, and the assignment that task's number, title and whether it is extra credit. A
 * test of a task the assignment does not choose counts toward nothing (that code ships solved).
 * (A class, not a record: Debian's Gradle 4.4 calls a record's class file malformed.)
 */
final class GradedTask {
    private final int number;
    private final String title;
    private final boolean extraCredit;

    private GradedTask(int number, String title, boolean extraCredit) {
        this.number = number;
        this.title = title;
        this.extraCredit = extraCredit;
    }

    int number() {
        return number;
    }

    String title() {
        return title;
    }

    boolean extraCredit() {
        return extraCredit;
    }

    /** The graded task of test class {@code className}, or empty when it belongs to no chosen task. */
    static Optional<GradedTask> of(String className) {
        Assignment assignment = Assignment.current();
        Optional<Task> task = assignment.table().ofTestClass(className).filter(t -> assignment.isChosen(t.id()));
        return task.map(t -> new GradedTask(assignment.number(t.id()), t.title(), assignment.isExtraCredit(t.id())));
    }
}
