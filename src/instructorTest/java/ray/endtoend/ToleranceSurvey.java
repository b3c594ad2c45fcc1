package ray.endtoend;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.function.Function;
import ray.image.ImageDiff;
import ray.image.PngReader;
import ray.scene.SceneFiles;

/**
 * Measures the figures behind {@link ImageDiff}'s constants: for every shipped scene, the share of
 * pixels that differ from the reference by more than 1, 2 and 3 levels, for correct variants and
 * for defects ({@link Variants}). Not a test: run it by hand after changing scenes or the
 * renderer, and update docs/grading.md and ImageDiff's javadoc with what it prints.
 *
 * <pre>java -cp MAIN-AND-TEST-CLASSES ray.endtoend.ToleranceSurvey   (from the project folder)</pre>
 */
public final class ToleranceSurvey {
    private ToleranceSurvey() {
    }

    public static void main(String[] args) throws Exception {
        Map<String, Function<Path, BufferedImage>> variants = new LinkedHashMap<>();
        variants.put("1 thread", f -> Variants.solution(f, 1));
        variants.put("3 threads", f -> Variants.solution(f, 3));
        variants.put("textbook sphere", Variants::textbookSpheres);
        variants.put("Moller-Trumbore", Variants::mollerTrumboreTriangles);
        variants.put("1-ulp + StrictMath.pow", Variants::ulpJitter);
        variants.put("half-pixel camera", Variants::halfPixelCamera);
        variants.put("flipped", f -> Variants.flipped(Variants.solution(f, 0)));
        variants.put("no shadows", Variants::withoutShadows);
        System.out.println("| scene | variant | max | mean | > 1 level | > 2 levels | > 3 levels | verdict |");
        System.out.println("| --- | --- | ---: | ---: | ---: | ---: | ---: | --- |");
        for (Path file : RenderScenes.sceneFiles()) {
            String name = SceneFiles.nameOf(file);
            BufferedImage reference = PngReader.read(RenderScenes.referenceOf(name));
            for (Map.Entry<String, Function<Path, BufferedImage>> v : variants.entrySet()) {
                BufferedImage image = v.getValue().apply(file);
                ImageDiff.Result r = ImageDiff.compare(reference, image);
                System.out.printf(Locale.ROOT, "| %s | %s | %d | %.3f | %s | %s | %s | %s |%n", name, v.getKey(), r.maxDifference(),
                        r.meanDifference(), share(reference, image, 1), share(reference, image, 2), share(reference, image, 3),
                        r.passed() ? "PASS" : "FAIL");
            }
        }
    }

    private static String share(BufferedImage reference, BufferedImage image, int levels) {
        ImageDiff.Result r = ImageDiff.compare(reference, image, levels, 0);
        return String.format(Locale.ROOT, "%.3f%% (%d)", 100 * r.differingShare(), r.differingPixels());
    }
}
