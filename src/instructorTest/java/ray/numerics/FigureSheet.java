package ray.numerics;

import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;

/**
 * Lays out the panels of one figure for {@link NumericsFigures}: a grid of equally sized pictures,
 * each with a one-line caption under it, on a white sheet, so that the PNG reads on its own in a
 * Markdown viewer. Also the pixel operations the figures need: crop, nearest-neighbour enlargement
 * (each source pixel becomes a k×k block, no smoothing that could hide or invent a speck) and
 * counting.
 */
final class FigureSheet {
    private static final int GAP = 8;
    private static final int CAPTION_HEIGHT = 18;
    private static final Font FONT = new Font(Font.SANS_SERIF, Font.PLAIN, 12);

    /** One picture and the line under it. */
    static final class Panel {
        final BufferedImage picture;
        final String caption;

        Panel(BufferedImage picture, String caption) {
            this.picture = picture;
            this.caption = caption;
        }
    }

    private final int columns;
    private final List<Panel> panels = new ArrayList<>();

    FigureSheet(int columns) {
        this.columns = columns;
    }

    FigureSheet add(BufferedImage picture, String caption) {
        panels.add(new Panel(picture, caption));
        return this;
    }

    /** The sheet: panels left to right, top to bottom, each centred in a cell as large as the largest panel. */
    BufferedImage draw() {
        int cellWidth = 0;
        int cellHeight = 0;
        for (Panel p : panels) {
            cellWidth = Math.max(cellWidth, p.picture.getWidth());
            cellHeight = Math.max(cellHeight, p.picture.getHeight());
        }
        int rows = (panels.size() + columns - 1) / columns;
        int cols = Math.min(columns, panels.size());
        int width = GAP + cols * (cellWidth + GAP);
        int height = GAP + rows * (cellHeight + CAPTION_HEIGHT + GAP);
        BufferedImage sheet = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = sheet.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, width, height);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setFont(FONT);
        FontMetrics metrics = g.getFontMetrics();
        for (int k = 0; k < panels.size(); k++) {
            Panel p = panels.get(k);
            int x = GAP + (k % columns) * (cellWidth + GAP);
            int y = GAP + (k / columns) * (cellHeight + CAPTION_HEIGHT + GAP);
            g.drawImage(p.picture, x + (cellWidth - p.picture.getWidth()) / 2, y + (cellHeight - p.picture.getHeight()) / 2, null);
            int textWidth = metrics.stringWidth(p.caption);
            if (textWidth > cellWidth) {
                throw new IllegalArgumentException("caption wider than its panel (" + textWidth + " > " + cellWidth + "): " + p.caption);
            }
            g.setColor(Color.BLACK);
            g.drawString(p.caption, x + (cellWidth - textWidth) / 2, y + cellHeight + metrics.getAscent() + 2);
        }
        g.dispose();
        return sheet;
    }

    /** The w×h region of {@code picture} whose top-left pixel is (x, y) (rows from the top, as in the PNG). */
    static BufferedImage crop(BufferedImage picture, int x, int y, int w, int h) {
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                out.setRGB(i, j, picture.getRGB(x + i, y + j));
            }
        }
        return out;
    }

    /** Each pixel as a k×k block (nearest-neighbour enlargement). */
    static BufferedImage enlarge(BufferedImage picture, int k) {
        BufferedImage out = new BufferedImage(picture.getWidth() * k, picture.getHeight() * k, BufferedImage.TYPE_INT_RGB);
        for (int j = 0; j < out.getHeight(); j++) {
            for (int i = 0; i < out.getWidth(); i++) {
                out.setRGB(i, j, picture.getRGB(i / k, j / k));
            }
        }
        return out;
    }

    /** How many pixels are exactly {@code rgb} (0xRRGGBB). */
    static int count(BufferedImage picture, int rgb) {
        int n = 0;
        for (int j = 0; j < picture.getHeight(); j++) {
            for (int i = 0; i < picture.getWidth(); i++) {
                if ((picture.getRGB(i, j) & 0xffffff) == rgb) {
                    n++;
                }
            }
        }
        return n;
    }

    /**
     * How many pixels differ from {@code expected} by more than {@code levels} in some channel (the
     * same rule as ray.image.ImageDiff with its tolerance of 2 levels).
     */
    static int differing(BufferedImage expected, BufferedImage actual, int levels) {
        int n = 0;
        for (int j = 0; j < expected.getHeight(); j++) {
            for (int i = 0; i < expected.getWidth(); i++) {
                if (difference(expected.getRGB(i, j), actual.getRGB(i, j)) > levels) {
                    n++;
                }
            }
        }
        return n;
    }

    /** The largest channel difference between two 0xRRGGBB pixels. */
    static int difference(int a, int b) {
        int d = 0;
        for (int shift = 0; shift <= 16; shift += 8) {
            d = Math.max(d, Math.abs(((a >> shift) & 0xff) - ((b >> shift) & 0xff)));
        }
        return d;
    }
}
