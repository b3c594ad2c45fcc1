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

    private Variant(String name, int task, boolean correct) {
        this.name = name;
        this.task = task;
        this.correct = correct;
    }

    static Variant correct(String name, int task) {
        return new Variant(name, task, true);
    }

    static Variant wrong(String name, int task) {
        return new Variant(name, task, false);
    }

    Path folder() {
        return ROOT.resolve(name);
    }

    @Override
    public String toString() {
        return name + " (Task " + task + (correct ? ", correct" : ", known wrong") + ")";
    }
}
