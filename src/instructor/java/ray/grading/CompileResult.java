package ray.grading;

/** The outcome of compiling a project tree: success, and the compiler's messages (errors first). */
public record CompileResult(boolean ok, String messages) {
}
