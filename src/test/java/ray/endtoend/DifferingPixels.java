package ray.endtoend;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import ray.image.ImageDiff;
import ray.render.PixelKinds;
import ray.surface.SurfaceKind;

/**
 * A failed render's differing pixels in words, for the render test's message: what they show in
 * <em>your</em> render (spheres, triangles, cylinders or the background, each with the task whose
 * code drew it), and the worst of them with the command that explains it:
 *
 * <pre>
 * 393 pixels differ; 380 of them are on triangles (Task 3), 13 on the background.
 * The worst pixel is (150, 149): see how your code lit it with `ray1 trace scenes/x.xml 150 149` (or explore it with `ray1 explore scenes/x.xml`)
 * </pre>
 *
 * <p>The kinds come from the render being judged ({@link ray.render.Renderer#renderWithKinds()}):
 * what your own intersection code reported as each pixel's closest hit. A pixel your triangles
 * wrongly cover counts as a triangle, one they wrongly miss as the background.
 */
final class DifferingPixels {
    private DifferingPixels() {
    }

    /**
     * The lines that follow the render test's summary: each begins ".\n    ", ending the line before
     * it, and the last has no full stop. Empty when the sizes differ (no pixel can be matched) or
     * nothing differs; without {@code kinds}, the worst pixel alone.
     *
     * @param scene the scene file as the message names it (scenes/x.xml)
     */
    /** The same as sentences, one per line, each ending with a period; none when no pixel differs. */
    static List<String> lines(ImageDiff.Result result, PixelKinds kinds, Path scene) {
        List<String> lines = new ArrayList<>();
        if (result.sameSize() && result.differingPixels() > 0) {
            if (kinds != null) {
                lines.add(onKinds(result, kinds) + ".");
            }
            lines.add(worstPixel(result, scene) + ".");
        }
        return lines;
    }

    static String sentences(ImageDiff.Result result, PixelKinds kinds, Path scene) {
        String joined = String.join("\n    ", lines(result, kinds, scene));
        return joined.isEmpty() ? "" : ".\n    " + joined.substring(0, joined.length() - 1);
    }

    /**
     * "393 pixels differ; 380 of them are on triangles (Task 3), 13 on the background": every kind
     * that any differing pixel shows, the most first (ties in {@link SurfaceKind}'s order), the
     * counts adding up to the differing pixels.
     */
    static String onKinds(ImageDiff.Result result, PixelKinds kinds) {
        Map<SurfaceKind, Integer> counts = counts(result, kinds);
        List<SurfaceKind> order = new ArrayList<>(counts.keySet());
        // Stable: equal counts stay in the enum's order.
        order.sort((a, b) -> Integer.compare(counts.get(b), counts.get(a)));
        int total = result.differingPixels();
        if (total == 1) {
            return "1 pixel differs, on " + order.get(0).phrase(1);
        }
        StringBuilder text = new StringBuilder().append(total).append(" pixels differ; ");
        for (int k = 0; k < order.size(); k++) {
            SurfaceKind kind = order.get(k);
            int n = counts.get(kind);
            if (k == 0) {
                text.append(n).append(n == 1 ? " of them is on " : " of them are on ");
            } else {
                text.append(", ").append(n).append(" on ");
            }
            text.append(kind.phrase(n));
        }
        return text.toString();
    }

    /** How many differing pixels show each kind, in your render; kinds that none shows are left out. */
    static Map<SurfaceKind, Integer> counts(ImageDiff.Result result, PixelKinds kinds) {
        Map<SurfaceKind, Integer> counts = new EnumMap<>(SurfaceKind.class);
        for (int y = 0; y < kinds.height(); y++) {
            for (int x = 0; x < kinds.width(); x++) {
                if (result.differsAt(x, y)) {
                    counts.merge(kinds.at(x, y), 1, Integer::sum);
                }
            }
        }
        return counts;
    }

    /**
     * "The worst pixel is (x, y): see how your code lit it with `ray1 trace scenes/x.xml x y` (or explore
     * it with `ray1 explore scenes/x.xml`)": x from the left and y from the top, as ray1 trace counts.
     */
    static String worstPixel(ImageDiff.Result result, Path scene) {
        ImageDiff.Pixel worst = result.worstPixel();
        return "The worst pixel is " + worst + ": see how your code lit it with `ray1 trace " + scene + " " + worst.x() + " "
                + worst.y() + "` (or explore it with `ray1 explore " + scene + "`)";
    }
}
