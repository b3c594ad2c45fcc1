package ray.numerics;

import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Locale;
import ray.image.ImageDiff;
import ray.math.Vec3;

/**
 * Prints, for docs/numerics.md, how the shipped scenes' full-size renders change when the whole
 * scene is moved or scaled ({@link MovedScenes}), with the renderer's offsets and with shadow rays
 * from a fixed t_min, as a markdown table of pixels that differ by more than 2 levels from the
 * scene's own render at scale 1 at the origin. {@link SceneInvarianceTest} checks the same at a
 * third of the size. Usage: {@code SceneInvarianceSurvey} (about a minute).
 */
public final class SceneInvarianceSurvey {
    private SceneInvarianceSurvey() {
    }

    public static void main(String[] args) {
        List<String> scenes = List.of("two-boxes", "wire-box", "glazed-sphere", "mesh-flat", "mesh-smooth", "group-transforms");
        System.out.println("| scene | translated by 1e5 | scaled by 1e-3 | both (1e-3, then moved by (−3e4, 2e4, 5e4)) |");
        System.out.println("| --- | ---: | ---: | ---: |");
        for (String scene : scenes) {
            BufferedImage original = MovedScenes.render(MovedScenes.load(scene, 1, Vec3.ZERO, 1));
            System.out.printf(Locale.ROOT, "| %s | %s | %s | %s |%n", scene,
                    cell(original, MovedScenes.render(MovedScenes.load(scene, 1, new Vec3(1e5, 1e5, 1e5), 1))),
                    cell(original, MovedScenes.render(MovedScenes.load(scene, 1e-3, Vec3.ZERO, 1))),
                    cell(original, MovedScenes.render(MovedScenes.load(scene, 1e-3, new Vec3(-3e4, 2e4, 5e4), 1))));
        }
        System.out.println();
        System.out.println("Shadow rays from a fixed t_min (one sample per pixel), against the same at scale 1:");
        System.out.println();
        System.out.println("| scene | t_min | scaled by 1e-3 | translated by 1e5 |");
        System.out.println("| --- | --- | ---: | ---: |");
        for (String scene : List.of("two-boxes", "wire-box", "mesh-flat", "mesh-smooth")) {
            for (double epsilon : new double[] {1e-3, 1e-6}) {
                BufferedImage original = MovedScenes.renderWithFixedEpsilon(MovedScenes.load(scene, 1, Vec3.ZERO, 1), epsilon);
                System.out.printf(Locale.ROOT, "| %s | %g | %s | %s |%n", scene, epsilon,
                        cell(original, MovedScenes.renderWithFixedEpsilon(MovedScenes.load(scene, 1e-3, Vec3.ZERO, 1), epsilon)),
                        cell(original, MovedScenes.renderWithFixedEpsilon(MovedScenes.load(scene, 1, new Vec3(1e5, 1e5, 1e5), 1), epsilon)));
            }
        }
    }

    private static String cell(BufferedImage expected, BufferedImage actual) {
        ImageDiff.Result r = ImageDiff.compare(expected, actual);
        return String.format(Locale.ROOT, "%d px (%.3f%%), max %d%s", r.differingPixels(), 100 * r.differingShare(),
                r.maxDifference(), r.passed() ? "" : " FAIL");
    }
}
