package ray.testing;

/** When a graded test's result is shown to the student (Gradescope's four settings). */
public enum Visibility {
    VISIBLE("visible"),
    HIDDEN("hidden"),
    AFTER_DUE_DATE("after_due_date"),
    AFTER_PUBLISHED("after_published");

    /** The value Gradescope's results.json uses. */
    public final String gradescope;

    Visibility(String gradescope) {
        this.gradescope = gradescope;
    }
}
