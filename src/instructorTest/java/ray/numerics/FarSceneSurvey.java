package ray.numerics;

import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Locale;
import ray.image.ImageDiff;
import ray.math.Vec3;

/**
 * The table behind docs/numerics.md's "far from the origin": shipped scenes with contact shadows
 * moved by 10⁶ … 10¹² ({@link FarScenes}) or scaled by 10⁻⁴ and 10⁴ ({@link MovedScenes}),
 * rendered in the scene's own coordinates (before) and from the camera's frame (now), each
 * compared with the same scene unmoved: pixels more than 2 levels off. Run with the test classpath.
 */
public final class FarSceneSurvey {
    private FarSceneSurvey() {
    }

    public static void main(String[] args) {
        int shrink = args.length > 0 ? Integer.parseInt(args[0]) : 2;
        double[] distances = {1e6, 1e9, 3e11, 1e12};
        double[] scales = {1e-4, 1e4};
        StringBuilder head = new StringBuilder("| scene | frame |");
        for (double d : distances) {
            head.append(String.format(Locale.ROOT, " moved %.0e |", d));
        }
        for (double s : scales) {
            head.append(String.format(Locale.ROOT, " scaled %.0e |", s));
        }
        System.out.println(head);
        System.out.println("| --- | --- |" + " ---: |".repeat(distances.length + scales.length));
        for (String scene : List.of("two-boxes", "glazed-sphere", "mesh-smooth")) {
            BufferedImage original = FarScenes.render(FarScenes.load(scene, Vec3.ZERO, shrink));
            for (boolean world : new boolean[] {true, false}) {
                StringBuilder row = new StringBuilder("| " + scene + " | " + (world ? "scene's own (before)" : "camera's (now)") + " |");
                for (double d : distances) {
                    var moved = FarScenes.load(scene, new Vec3(d, d, d), shrink);
                    row.append(' ').append(cell(original, world ? FarScenes.renderInWorldFrame(moved) : FarScenes.render(moved))).append(" |");
                }
                for (double s : scales) {
                    var scaled = MovedScenes.load(scene, s, Vec3.ZERO, shrink);
                    row.append(' ').append(cell(original, world ? FarScenes.renderInWorldFrame(scaled) : FarScenes.render(scaled))).append(" |");
                }
                System.out.println(row);
            }
        }
    }

    private static String cell(BufferedImage expected, BufferedImage actual) {
        ImageDiff.Result r = ImageDiff.compare(expected, actual);
        return String.format(Locale.ROOT, "%d (%.2f%%)", r.differingPixels(), 100 * r.differingShare());
    }
}
