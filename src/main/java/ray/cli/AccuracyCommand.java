package ray.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import ray.accuracy.AccuracyStudy;
import ray.accuracy.ReportWriter;
import ray.accuracy.SceneStudy;
import ray.accuracy.Sweeps;
import ray.render.PixelWindow;
import ray.scene.Scene;
import ray.scene.SceneOptions;

/** {@code ray1 accuracy}: the accuracy–cost study of scenes, written as a report (DIR/index.html). */
@Command(name = "accuracy", mixinStandardHelpOptions = true,
        description = {"Renders each scene over sweeps of samples per pixel (grid and jittered), secondary-ray offsets and, in "
            + "the instructor's copy, float vs double and textbook vs robust intersection; measures time and error against a "
            + "converged reference on a window of the image; writes DIR/index.html with tables, plots and image strips."})
public final class AccuracyCommand extends ManyScenesCommand {
    @Option(names = {"-o", "--output"}, paramLabel = "DIR", description = "Report folder (default: ${DEFAULT-VALUE}).")
    Path output = Path.of("build/accuracy");

    @Option(names = "--samples", paramLabel = "N,N,...", split = ",", description = "Samples-per-pixel sweep (default: 1,4,16,64,256).")
    List<Integer> samples = new ArrayList<>(Sweeps.SAMPLES);

    @Option(names = "--reference-samples", paramLabel = "N", description = "Samples per pixel of the converged reference "
            + "(default: ${DEFAULT-VALUE}).")
    int referenceSamples = AccuracyStudy.REFERENCE_SAMPLES;

    @Option(names = "--window", paramLabel = "X,Y,W,H", description = "The pixels to measure (Y from the top); default: the "
            + "--window-size square with the most edges.")
    String window;

    @Option(names = "--window-size", paramLabel = "N", description = "Side of the chosen window (default: ${DEFAULT-VALUE}).")
    int windowSize = AccuracyStudy.WINDOW_SIZE;

    @Option(names = "--runs", paramLabel = "N", description = "Timed runs per setting, at least 3 (default: ${DEFAULT-VALUE}).")
    int runs = AccuracyStudy.RUNS;

    @Option(names = "--threads", paramLabel = "N", description = "Worker threads of the timed renders (default: 1, the "
            + "steadiest clock; the reference and the whole-image renders use every core).")
    Integer threads;

    @Option(names = "--quiet", description = "Do not print a line per measured setting.")
    boolean quiet;

    @Override
    public Integer call() throws IOException {
        PixelWindow part = checkOptions();
        SceneOptions sceneOptions = courseOptions.sceneOptions(spec.commandLine());
        PrintWriter out = out();
        PrintWriter err = err();
        if (!outputUsable(output, "write the report somewhere else, e.g. -o build/accuracy")) {
            return 1;
        }
        List<Path> files = scenes.files(err);
        if (files == null) {
            return 1;
        }
        AccuracyStudy study = new AccuracyStudy(samples, windowSize, part, referenceSamples, runs, threads == null ? 1 : threads,
                line -> {
                    if (!quiet) {
                        out.println(line);
                        out.flush();
                    }
                });
        List<SceneStudy> studies = new ArrayList<>();
        int failures = eachScene(files, file -> {
            Scene scene = SceneWarnings.load(file, sceneOptions, err);
            if (part != null && !part.fitsIn(scene.getWidth(), scene.getHeight())) {
                err.println("error: " + file + ": the window " + part + " does not fit in its " + scene.getWidth() + "x"
                        + scene.getHeight() + " image");
                return false;
            }
            studies.add(study.study(scene));
            return true;
        });
        if (!studies.isEmpty()) {
            ReportWriter.write(studies, output, "ray1 " + String.join(" ", spec.commandLine().getParseResult().originalArgs()));
            out.println("report: " + output.resolve("index.html") + " (" + studies.size() + " scene" + (studies.size() == 1 ? "" : "s") + ")");
            List<String> missing = studies.get(0).missing;
            if (!missing.isEmpty()) {
                out.println("not in this copy: the " + String.join(" and ", missing) + " sweeps (see docs/accuracy.md)");
            }
        }
        if (failures > 0) {
            err.println(failures + " of " + files.size() + " scenes failed");
        }
        return failures == 0 ? 0 : 1;
    }

    /** Rejects options no study can use, with picocli's one-line usage error; returns the parsed --window. */
    private PixelWindow checkOptions() {
        CommandLine cl = spec.commandLine();
        if (samples.isEmpty() || new HashSet<>(samples).size() != samples.size()) {
            throw new CommandLine.ParameterException(cl, "--samples must be distinct counts, e.g. 1,4,16, got " + samples);
        }
        OptionChecks.samples(cl, "--reference-samples", referenceSamples);
        for (int n : samples) {
            if (n < 1 || n >= referenceSamples) {
                throw new CommandLine.ParameterException(cl, "--samples must lie between 1 and --reference-samples − 1 ("
                        + (referenceSamples - 1) + "), got " + n);
            }
        }
        if (runs < 3) {
            throw new CommandLine.ParameterException(cl, "--runs must be at least 3 (a median with a spread), got " + runs);
        }
        OptionChecks.atLeastOne(cl, "--window-size", windowSize);
        OptionChecks.atLeastOne(cl, "--threads", threads);
        try {
            return window == null ? null : PixelWindow.parse(window);
        } catch (IllegalArgumentException e) {
            throw new CommandLine.ParameterException(cl, "--window: " + e.getMessage());
        }
    }
}
