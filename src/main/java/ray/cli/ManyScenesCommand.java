package ray.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import ray.scene.SceneException;

/**
 * What the commands that take many scenes ({@code render}, {@code accuracy}) share: the scene
 * arguments, {@code --verbose}, and the loop that runs each scene in turn, so that one scene's
 * error is one line and the others still run.
 */
abstract class ManyScenesCommand implements Callable<Integer> {
    /** One scene file's work; false when it failed and said so on err already. */
    interface SceneWork {
        boolean run(Path file) throws IOException;
    }

    @CommandLine.Mixin
    Verbosity verbosity;

    @CommandLine.Mixin
    SceneArguments scenes;

    @CommandLine.Mixin
    CourseOptions courseOptions;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    PrintWriter out() {
        return spec.commandLine().getOut();
    }

    PrintWriter err() {
        return spec.commandLine().getErr();
    }

    /** Whether the output folder is usable; if not, says why on err ("error: …, {@code hint}"). */
    boolean outputUsable(Path folder, String hint) {
        String problem = OptionChecks.outputFolderProblem(folder, hint);
        if (problem != null) {
            err().println("error: " + problem);
        }
        return problem == null;
    }

    /**
     * Runs {@code work} on each file in turn: a scene error is its one line, any other failure is
     * reported as {@code --verbose} says, and the next file still runs.
     *
     * @return how many files failed
     */
    int eachScene(List<Path> files, SceneWork work) {
        PrintWriter err = err();
        int failures = 0;
        for (Path file : files) {
            try {
                if (!work.run(file)) {
                    failures++;
                }
            } catch (SceneException e) {
                err.println("error: " + e.getMessage());
                failures++;
            } catch (IOException | RuntimeException e) {
                verbosity.report(err, file.toString(), e);
                failures++;
            }
            out().flush();
            err.flush();
        }
        return failures;
    }
}
