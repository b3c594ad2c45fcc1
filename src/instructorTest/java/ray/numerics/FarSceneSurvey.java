package ray.numerics;

import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Locale;
import ray.image.ImageDiff;
import ray.math.Vec3;

/**
 * The table behind docs/numerics.md's "far from the origin": shipped scenes with contact shadows
 * moved by 10⁶ … 10¹² ({@link FarScenes}) or scaled by 10⁻⁴ and 10⁴ ({@link MovedScenes}),
 * rendered in the scene's own coordinates (before) and from the camera's frame (now), with the
 * solution's intersection and with textbook intersection, each compared with the same scene unmoved: pixels more than 2 levels off. Run with the test classpath.
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
            BufferedImage textbookOriginal = FarScenes.renderTextbook(FarScenes.load(scene, Vec3.ZERO, shrink), false);
            for (int variant = 0; variant < 4; variant++) {
                boolean world = variant % 2 == 0;
                boolean textbook = variant >= 2;
                String frame = world ? "scene's own (before)" : "camera's (now)";
                StringBuilder row = new StringBuilder("| " + scene + " | " + (textbook ? "textbook, " : "") + frame + " |");
                BufferedImage base = textbook ? textbookOriginal : original;
                for (double d : distances) {
                    var moved = FarScenes.load(scene, new Vec3(d, d, d), shrink);
                    row.append(' ').append(cell(base, render(moved, world, textbook))).append(" |");
                }
                for (double s : scales) {
                    var scaled = MovedScenes.load(scene, s, Vec3.ZERO, shrink);
                    row.append(' ').append(cell(base, render(scaled, world, textbook))).append(" |");
                }
                System.out.println(row);
            }
        }
    }

    private static BufferedImage render(ray.scene.Scene scene, boolean world, boolean textbook) {
        if (textbook) {
            return FarScenes.renderTextbook(scene, world);
        }
        return world ? FarScenes.renderInWorldFrame(scene) : FarScenes.render(scene);
    }

    private static String cell(BufferedImage expected, BufferedImage actual) {
        ImageDiff.Result r = ImageDiff.compare(expected, actual);
        return String.format(Locale.ROOT, "%d (%.2f%%)", r.differingPixels(), 100 * r.differingShare());
    }
}
