package ray.grading;

import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Base64;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.imageio.ImageIO;
import ray.image.ImageDiff;

/**
 * Pictures for a failed render test, for the platform to show beside its message: the student's
 * render, the reference and the heat map of their difference (written by the render test into the
 * grading tree's build/reports/render-diff, which the student cannot open), each shrunk to
 * {@link #WIDTH} pixels across and inlined as a data URL, and the one {@code ray1 trace} command
 * that explains the pixel where the two differ most. The message's own pointer to the report, a
 * path on the grading machine, is left out.
 */
final class RenderFeedback {
    /** Width of the inlined pictures: small enough for a results file of many failures, large enough to see what is wrong. */
    static final int WIDTH = 160;
    private static final String REPORT_LINE = "See your image, the reference and where they differ in";

    private RenderFeedback() {
    }

    /** What one failed render test shows: as an HTML page (Gradescope), or as images and advice (PrairieLearn). */
    static final class Shown {
        final String html;
        /** The three pictures as PrairieLearn's {label, url} entries, url a data URL. */
        final List<Map<String, Object>> images;
        /** The known mistake the render is, or null. */
        final String advice;

        Shown(String html, List<Map<String, Object>> images, String advice) {
            this.html = html;
            this.images = images;
            this.advice = advice;
        }
    }

    /**
     * For each failed render test whose pictures exist under {@code tree}: its id → what to show. The
     * first failed render of each task gets the three pictures; the others their message, the
     * mistake's name and the trace command, since a stub handout fails 22 renders, whose pictures
     * alone would come near the results file's limit.
     */
    static Map<String, Shown> of(List<TestOutcome> outcomes, Path tree, Map<String, String> mistakeNames) {
        Map<String, Shown> html = new LinkedHashMap<>();
        Set<Integer> pictured = new HashSet<>();
        for (TestOutcome t : outcomes) {
            FailedRender failed = FailedRender.of(t, tree);
            if (failed == null || !Files.isRegularFile(failed.reference)) {
                continue;
            }
            try {
                BufferedImage difference = Files.isRegularFile(failed.difference) ? ImageIO.read(failed.difference.toFile()) : null;
                html.put(t.id(), page(t.message(), failed.sceneFile, ImageIO.read(failed.yours.toFile()),
                        ImageIO.read(failed.reference.toFile()), difference, mistakeNames.get(t.id()), pictured.add(t.task())));
            } catch (IOException | RuntimeException e) {
                // No pictures for this test: its message alone still says what is wrong.
            }
        }
        return html;
    }

    /**
     * The message without the render test's pointer to its report: a file:// address on the grading
     * machine, in a folder deleted when grading ends, which only confuses a student who reads it.
     */
    static String withoutReportLine(String message) {
        if (!message.contains(REPORT_LINE)) {
            return message;
        }
        StringBuilder kept = new StringBuilder();
        for (String line : message.split("\n", -1)) {
            if (!line.strip().startsWith(REPORT_LINE)) {
                kept.append(kept.length() == 0 ? "" : "\n").append(line);
            }
        }
        return kept.toString();
    }

    private static Shown page(String message, String sceneFile, BufferedImage yours, BufferedImage reference, BufferedImage difference,
            String knownMistake, boolean withPictures) throws IOException {
        // Long lines wrap inside the box instead of running past it.
        StringBuilder html = new StringBuilder("<pre style=\"white-space: pre-wrap\">").append(escape(withoutReportLine(message).strip()))
                .append("</pre>\n");
        // A flip or mirror has the fuller advice; the known-wrong versions' names come next.
        String flipped = KnownMistakes.of(yours, reference);
        String mistake = flipped != null ? flipped : knownMistake;
        if (mistake != null) {
            html.append("<p><strong>").append(escape(mistake)).append("</strong></p>\n");
        }
        List<Map<String, Object>> images = new java.util.ArrayList<>();
        if (withPictures) {
            // A row of pictures with a row of captions under them.
            StringBuilder pictures = new StringBuilder("<table><tr>");
            StringBuilder captions = new StringBuilder("<tr>");
            figure(yours, "your render", images, pictures, captions);
            figure(reference, "the reference", images, pictures, captions);
            if (difference != null) {
                figure(difference, "where they differ", images, pictures, captions);
            }
            html.append(pictures).append("</tr>").append(captions).append("</tr></table>\n");
        } else {
            html.append("<p>(Pictures are shown for the first failed render of each task only, to keep the results small.)</p>\n");
        }
        int[] worst = worstPixel(yours, reference);
        if (worst != null) {
            html.append("<p>They differ most at pixel (").append(worst[0]).append(", ").append(worst[1])
                    .append(") (from the left and from the top). See why your code colors it so:</p>\n<pre>gradle run --args=\"trace ")
                    .append(escape(sceneFile)).append(' ').append(worst[0]).append(' ').append(worst[1]).append("\"</pre>\n");
        }
        return new Shown(html.toString(), images, mistake);
    }

    /** The pixel (x from the left, y from the top) where the two differ most in any channel, or null when their sizes differ. */
    static int[] worstPixel(BufferedImage a, BufferedImage b) {
        // The render tests' own per-pixel difference and worst pixel, as their failure message names it.
        ImageDiff.Result diff = ImageDiff.compare(a, b);
        if (!diff.sameSize()) {
            return null;
        }
        ImageDiff.Pixel worst = diff.worstPixel();
        return new int[] {worst.x(), worst.y()};
    }

    /** Adds the picture as PrairieLearn's {label, url} and as a table cell, its caption to the row below. */
    private static void figure(BufferedImage image, String caption, List<Map<String, Object>> images, StringBuilder pictures,
            StringBuilder captions) throws IOException {
        String url = "data:image/png;base64," + base64(shrunk(image));
        images.add(Map.of("label", caption, "url", url));
        pictures.append("<td><img alt=\"").append(caption).append("\" title=\"").append(caption).append("\" src=\"").append(url)
                .append("\"></td>");
        captions.append("<td>").append(caption).append("</td>");
    }

    private static BufferedImage shrunk(BufferedImage image) {
        if (image.getWidth() <= WIDTH) {
            return image;
        }
        int height = Math.max(1, Math.round((float) image.getHeight() * WIDTH / image.getWidth()));
        BufferedImage small = new BufferedImage(WIDTH, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = small.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BILINEAR);
        g.drawImage(image, 0, 0, WIDTH, height, null);
        g.dispose();
        return small;
    }

    private static String base64(BufferedImage image) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ImageIO.write(image, "png", bytes);
        return Base64.getEncoder().encodeToString(bytes.toByteArray());
    }

    static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
