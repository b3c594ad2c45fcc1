package ray.cli;

import java.io.PrintWriter;
import picocli.CommandLine.Option;

/**
 * The {@code --verbose} option, mixed into every command, and the one way a command reports a
 * failure it did not foresee: a line, and the stack trace only when asked for.
 */
final class Verbosity {
    @Option(names = "--verbose", description = "Show the stack trace of unexpected failures.")
    boolean on;

    /** Prints "error: WHERE: what happened (at File.java:N; ...)" and, with --verbose, the stack trace. */
    void report(PrintWriter err, String where, Throwable e) {
        err.println("error: " + (where != null ? where + ": " : "") + Errors.oneLine(e));
        if (on) {
            e.printStackTrace(err);
        }
    }
}
