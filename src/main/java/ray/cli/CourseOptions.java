package ray.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine;
import picocli.CommandLine.Option;
import ray.scene.SceneOptions;
import ray.shading.Course;
import ray.shading.MicrofacetFactor;

/**
 * {@code --course}, {@code --scene-root} and {@code --microfacet-term}, mixed into every command
 * that loads scenes (render, trace, explore, accuracy): which course's conventions a scene renders
 * by, where its data paths start, and whether its microfacet shaders show one factor alone.
 */
final class CourseOptions {
    @Option(names = "--course", paramLabel = "YEAR", description = "The course conventions to render by: 2017 or 2019"
            + " (default: a scene under scenes/ 2017, under scenes-2019/ 2019, any other the assignment's). 2019 shades with BRDFs"
            + " (Lambertian ρd/π), blackens surfaces seen from behind and reads <mirrorCoefficient>.")
    String course;

    @Option(names = "--scene-root", paramLabel = "DIR", description = "The folder that relative mesh and texture paths"
            + " start from (default: the scene file's folder, or the nearest folder above it that has the file).")
    Path sceneRoot;

    @Option(names = "--microfacet-term", paramLabel = "D|F|G", description = "Show one factor of every microfacet shader alone,"
            + " as the course's debug images did: k_mf times D (the distribution of facet normals), F (the Fresnel factor) or G"
            + " (G1(l)·G1(v)), lit as the BRDF would be, with no diffuse part.")
    String microfacetTerm;

    /** The options as the loader takes them; a bad --course, --scene-root or --microfacet-term is a usage error naming it. */
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
        SceneOptions options = SceneOptions.orAssignment(chosen, sceneRoot);
        if (microfacetTerm != null) {
            try {
                options = options.withMicrofacetFactor(MicrofacetFactor.of(microfacetTerm));
            } catch (IllegalArgumentException e) {
                throw new CommandLine.ParameterException(cl, "--microfacet-term must be D, F or G, got '" + microfacetTerm + "'");
            }
        }
        return options;
    }
}
