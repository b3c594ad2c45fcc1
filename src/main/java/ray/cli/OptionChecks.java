package ray.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine;
import ray.scene.Limits;

/**
 * Range checks of numeric options shared by the commands. A bad value is picocli's usage error:
 * one line naming the option, then the usage, and exit status 2.
 */
final class OptionChecks {
    private OptionChecks() {
    }

    /** An optional count that must be at least 1 when given. */
    static void atLeastOne(CommandLine cl, String option, Integer value) {
        if (value != null && value < 1) {
            throw new CommandLine.ParameterException(cl, option + " must be at least 1, got " + value);
        }
    }

    /** The value of {@code --accel}: {@code bvh} (or {@code framework}), {@code student} or {@code none}. */
    static ray.accel.Acceleration acceleration(CommandLine cl, String option, String value) {
        ray.accel.Acceleration mode = ray.accel.Acceleration.named(value);
        if (mode == null) {
            throw new CommandLine.ParameterException(cl, option + " must be " + ray.accel.Acceleration.spellings() + ", got '" + value + "'");
        }
        return mode;
    }

    /** An optional samples-per-pixel count: between 1 and {@link Limits#MAX_SAMPLES}. */
    static void samples(CommandLine cl, String option, Integer value) {
        atLeastOne(cl, option, value);
        if (value != null && value > Limits.MAX_SAMPLES) {
            throw new CommandLine.ParameterException(cl, option + " must be at most " + Limits.MAX_SAMPLES + ", got " + value);
        }
    }

    /**
     * Why files may not be written into {@code output}, or null: it is a file, or it holds the reference
     * images (marked by {@link RenderCommand#REFERENCE_MARKER}), which only {@code gradle references} may write.
     */
    static String outputFolderProblem(Path output, String elsewhere) {
        if (Files.exists(output) && !Files.isDirectory(output)) {
            return output + " is a file; expected a folder (-o DIR)";
        }
        if (Files.exists(output.resolve(RenderCommand.REFERENCE_MARKER))) {
            return output + " holds the reference images (it has a " + RenderCommand.REFERENCE_MARKER + " file); " + elsewhere;
        }
        return null;
    }
}
