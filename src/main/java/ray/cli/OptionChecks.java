package ray.cli;

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

    /** An optional samples-per-pixel count: between 1 and {@link Limits#MAX_SAMPLES}. */
    static void samples(CommandLine cl, String option, Integer value) {
        atLeastOne(cl, option, value);
        if (value != null && Limits.samplesProblem(value) != null) {
            throw new CommandLine.ParameterException(cl, option + " must be at most " + Limits.MAX_SAMPLES + ", got " + value);
        }
    }
}
