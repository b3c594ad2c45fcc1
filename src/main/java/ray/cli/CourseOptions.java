package ray.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine;
import picocli.CommandLine.Option;
import ray.scene.SceneOptions;
import ray.shading.Course;

/**
 * {@code --course} and {@code --scene-root}, mixed into every command that loads scenes (render,
 * trace, explore, accuracy): which course's conventions a scene renders by, and where its data
 * paths start.
 */
final class CourseOptions {
    @Option(names = "--course", paramLabel = "YEAR", description = "The course conventions to render by: 2017 or 2019"
            + " (default: a scene under scenes/ 2017, under scenes-2019/ 2019, any other the assignment's). 2019 shades with BRDFs"
            + " (Lambertian ρd/π), blackens surfaces seen from behind and reads <mirrorCoefficient>.")
    String course;

    @Option(names = "--scene-root", paramLabel = "DIR", description = "The folder that relative mesh and texture paths"
            + " start from (default: the scene file's folder, or the nearest folder above it that has the file).")
    Path sceneRoot;

    /** The options as the loader takes them; a bad --course or --scene-root is a usage error naming it. */
    SceneOptions sceneOptions(CommandLine cl) {
        Course chosen = null;
        if (course != null) {
            try {
                chosen = Course.of(course);
            } catch (IllegalArgumentException e) {
                throw new CommandLine.ParameterException(cl, "--course must be " + Course.years() + ", got '" + course + "'");
            }
        }
        if (sceneRoot != null && !Files.isDirectory(sceneRoot)) {
            throw new CommandLine.ParameterException(cl, "--scene-root " + sceneRoot + " is not a folder");
        }
        return SceneOptions.orAssignment(chosen, sceneRoot);
    }
}
