package ray.cli;

import java.io.PrintWriter;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The {@code ray1} command and its subcommands. */
@Command(name = "ray1", mixinStandardHelpOptions = true, version = "ray1 1.0",
        description = "The Ray I ray tracer: renders the course's XML scenes to PNG.",
        subcommands = {RenderCommand.class, DiffCommand.class, TraceCommand.class, ExploreCommand.class, AccuracyCommand.class})
public final class Ray1Command implements Runnable {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "a command is required, e.g. ray1 render scenes/");
    }

    /** Runs the command line and returns the exit status, printing to the standard streams. */
    public static int run(String... args) {
        return run(new PrintWriter(System.out, true), new PrintWriter(System.err, true), args);
    }

    public static int run(PrintWriter out, PrintWriter err, String... args) {
        CommandLine commandLine = new CommandLine(new Ray1Command());
        commandLine.setOut(out);
        commandLine.setErr(err);
        // A failure that escapes a command is reported in one line, and its stack trace only if that
        // command was given --verbose.
        commandLine.setExecutionExceptionHandler((e, cl, parseResult) -> {
            Object mixin = cl.getMixins().get("verbosity");
            (mixin instanceof Verbosity ? (Verbosity) mixin : new Verbosity()).report(cl.getErr(), null, e);
            return 1;
        });
        return commandLine.execute(args);
    }
}
