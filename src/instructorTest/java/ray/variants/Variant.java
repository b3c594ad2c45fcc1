package ray.variants;

import java.nio.file.Path;

/**
 * One way of writing a task's student files: a folder under {@code src/instructorTest/variants}
 * holding complete replacements of the task's files (by package path), and whether it is correct.
 */
final class Variant {
    static final Path ROOT = Path.of("src/instructorTest/variants");

    final String name;
    final int task;
    final boolean correct;
    /** Where its files are: a folder under {@link #ROOT}, or one a test wrote. */
    private final Path folder;

    private Variant(String name, int task, boolean correct, Path folder) {
        this.name = name;
        this.task = task;
        this.correct = correct;
        this.folder = folder;
    }

    private Variant(String name, int task, boolean correct) {
        this(name, task, correct, ROOT.resolve(name));
    }

    /** Files a test made (say, the handout's stubs of other tasks), in {@code folder}, graded as task {@code task}'s. */
    static Variant written(String name, int task, Path folder) {
        return new Variant(name, task, true, folder);
    }

    static Variant correct(String name, int task) {
        return new Variant(name, task, true);
    }

    static Variant wrong(String name, int task) {
        return new Variant(name, task, false);
    }

    Path folder() {
        return folder;
    }

    @Override
    public String toString() {
        return name + " (Task " + task + (correct ? ", correct" : ", known wrong") + ")";
    }
}
