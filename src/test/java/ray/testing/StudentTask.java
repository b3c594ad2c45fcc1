package ray.testing;

import java.util.List;
import java.util.stream.Collectors;
import ray.assignment.Assignment;
import ray.assignment.Task;
import ray.assignment.TaskTable;

/**
 * A task of this assignment as the tests name it: its number (its place in the assignment), title
 * and files. Which tasks there are, and which test classes belong to which, is written once, in the
 * table of tasks (src/main/resources/ray/assignment/tasks.properties); a test class finds its task
 * there by its name ({@link #ofTestClass}).
 */
public final class StudentTask {
    /** The table's id ("sphere"). */
    public final String id;
    /** Its number in this assignment, from 1; 0 when the assignment leaves it out. */
    public final int number;
    public final String title;
    /** The files the student edits for this task, relative to the project folder. */
    public final List<String> files;
    /** Whether every test of it is extra credit. */
    public final boolean extraCredit;

    private StudentTask(Task task, Assignment assignment) {
        this.id = task.id();
        this.number = assignment.number(task.id());
        this.title = task.title();
        this.files = task.projectFiles();
        this.extraCredit = assignment.isExtraCredit(task.id());
    }

    /**
     * The task with this id. One the assignment leaves out has number 0: its code ships solved and
     * its tests are not the student's (the handout leaves them out; the instructor's tree still runs them).
     */
    public static StudentTask of(String id) {
        Assignment assignment = Assignment.current();
        return new StudentTask(assignment.table().get(id), assignment);
    }

    /** The task a test class counts toward, by the table's test patterns. */
    public static StudentTask ofTestClass(Class<?> testClass) {
        return ofTestClass(testClass.getName());
    }

    public static StudentTask ofTestClass(String className) {
        Task task = TaskTable.standard().ofTestClass(className).orElseThrow(() -> new IllegalStateException(
                className + " matches no task's tests in " + TaskTable.PROJECT_FILE));
        return of(task.id());
    }

    /** The tasks of this assignment, in order. */
    public static List<StudentTask> values() {
        Assignment assignment = Assignment.current();
        return assignment.tasks().stream().map(t -> new StudentTask(t, assignment)).collect(Collectors.toList());
    }

    /** "Task 2 (Sphere)"; a task the assignment leaves out, "Sphere (not in this assignment)". */
    public String label() {
        return number == 0 ? title + " (not in this assignment)" : "Task " + number + " (" + title + ")";
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof StudentTask t && t.id.equals(id);
    }

    @Override
    public int hashCode() {
        return id.hashCode();
    }

    @Override
    public String toString() {
        return label();
    }
}
