package ray.accuracy;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * A log–log chart as a self-contained SVG document (no scripts, fonts or links, so it shows in
 * any browser offline): labelled points, lines through points (a Pareto front, a fitted power
 * law, an ideal rate), decade grid lines and a legend. Both axes span whole decades around the
 * data, so a slope reads off the grid: one decade across and half a decade down is −½.
 */
public final class LogLogPlot {
    static final int WIDTH = 640;
    static final int HEIGHT = 420;
    static final int LEFT = 70;
    static final int RIGHT = 20;
    static final int TOP = 36;
    static final int BOTTOM = 50;

    /** A point of a series, with an optional label written beside it (null for none). */
    public static final class Point {
        final double x;
        final double y;
        final String label;

        public Point(double x, double y, String label) {
            if (!(x > 0 && y > 0) || Double.isInfinite(x) || Double.isInfinite(y)) {
                throw new IllegalArgumentException("a log-log plot needs positive finite values, got (" + x + ", " + y + ")");
            }
            this.x = x;
            this.y = y;
            this.label = label;
        }
    }

    private static final class Series {
        final String name;
        final String color;
        final boolean line;
        final boolean dashed;
        final List<Point> points;

        Series(String name, String color, boolean line, boolean dashed, List<Point> points) {
            this.name = name;
            this.color = color;
            this.line = line;
            this.dashed = dashed;
            this.points = new ArrayList<>(points);
        }
    }

    private final String title;
    private final String xLabel;
    private final String yLabel;
    private final List<Series> series = new ArrayList<>();

    public LogLogPlot(String title, String xLabel, String yLabel) {
        this.title = title;
        this.xLabel = xLabel;
        this.yLabel = yLabel;
    }

    /** Points drawn as dots, each with its label; a null name leaves them out of the legend. */
    public LogLogPlot points(String name, String color, List<Point> points) {
        series.add(new Series(name, color, false, false, points));
        return this;
    }

    /** A polyline through the points in the order given. */
    public LogLogPlot line(String name, String color, boolean dashed, List<Point> points) {
        series.add(new Series(name, color, true, dashed, points));
        return this;
    }

    /** The chart as an SVG document. */
    public String toSvg() {
        List<Point> all = new ArrayList<>();
        series.forEach(s -> all.addAll(s.points));
        if (all.isEmpty()) {
            throw new IllegalStateException("a plot needs at least one point");
        }
        Axis x = Axis.around(all.stream().mapToDouble(p -> p.x).toArray(), LEFT, WIDTH - RIGHT);
        Axis y = Axis.around(all.stream().mapToDouble(p -> p.y).toArray(), HEIGHT - BOTTOM, TOP);
        StringBuilder svg = new StringBuilder();
        svg.append(String.format(Locale.ROOT, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
                + "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"12\">\n", WIDTH, HEIGHT, WIDTH, HEIGHT));
        svg.append(String.format(Locale.ROOT, "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", WIDTH, HEIGHT));
        svg.append(text(WIDTH / 2.0, 20, "middle", title, "font-size=\"14\" font-weight=\"bold\""));
        for (int k = x.lowDecade; k <= x.highDecade; k++) {
            double px = x.toPixel(Math.pow(10, k));
            svg.append(line(px, TOP, px, HEIGHT - BOTTOM, "#ddd", false));
            svg.append(text(px, HEIGHT - BOTTOM + 16, "middle", decade(k), ""));
        }
        for (int k = y.lowDecade; k <= y.highDecade; k++) {
            double py = y.toPixel(Math.pow(10, k));
            svg.append(line(LEFT, py, WIDTH - RIGHT, py, "#ddd", false));
            svg.append(text(LEFT - 6, py + 4, "end", decade(k), ""));
        }
        svg.append(String.format(Locale.ROOT, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" stroke=\"#444\"/>\n",
                LEFT, TOP, WIDTH - LEFT - RIGHT, HEIGHT - TOP - BOTTOM));
        svg.append(text((LEFT + WIDTH - RIGHT) / 2.0, HEIGHT - 12, "middle", xLabel, ""));
        svg.append(String.format(Locale.ROOT, "<text x=\"16\" y=\"%.1f\" text-anchor=\"middle\" transform=\"rotate(-90 16 %.1f)\">%s</text>\n",
                (TOP + HEIGHT - BOTTOM) / 2.0, (TOP + HEIGHT - BOTTOM) / 2.0, escape(yLabel)));
        for (Series s : series) {
            if (s.line) {
                StringBuilder pts = new StringBuilder();
                for (Point p : s.points) {
                    pts.append(String.format(Locale.ROOT, "%.1f,%.1f ", x.toPixel(p.x), y.toPixel(p.y)));
                }
                svg.append(String.format(Locale.ROOT, "<polyline points=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\"%s/>\n",
                        pts.toString().trim(), escape(s.color), s.dashed ? " stroke-dasharray=\"6 4\"" : ""));
            } else {
                for (Point p : s.points) {
                    svg.append(dot(x.toPixel(p.x), y.toPixel(p.y), s.color));
                    if (p.label != null) {
                        svg.append(text(x.toPixel(p.x) + 6, y.toPixel(p.y) - 6, "start", p.label, "font-size=\"10\""));
                    }
                }
            }
        }
        int entry = 0;
        for (Series s : series) {
            if (s.name == null) {
                continue; // drawn, but not in the legend (dots on a line that is)
            }
            double ly = TOP + 14 + 16 * entry++;
            double lx = WIDTH - RIGHT - 170;
            svg.append(s.line ? line(lx, ly - 4, lx + 18, ly - 4, s.color, s.dashed)
                    : dot(lx + 9, ly - 4, s.color));
            svg.append(text(lx + 24, ly, "start", s.name, ""));
        }
        return svg.append("</svg>\n").toString();
    }

    /** A log axis over whole decades, mapping a value to a pixel coordinate between two ends. */
    static final class Axis {
        final int lowDecade;
        final int highDecade;
        final double from;
        final double to;

        private Axis(int lowDecade, int highDecade, double from, double to) {
            this.lowDecade = lowDecade;
            this.highDecade = highDecade;
            this.from = from;
            this.to = to;
        }

        static Axis around(double[] values, double from, double to) {
            double min = Double.POSITIVE_INFINITY;
            double max = 0;
            for (double v : values) {
                min = Math.min(min, v);
                max = Math.max(max, v);
            }
            int low = (int) Math.floor(Math.log10(min));
            int high = (int) Math.ceil(Math.log10(max));
            return new Axis(low, high > low ? high : low + 1, from, to);
        }

        double toPixel(double value) {
            return from + (Math.log10(value) - lowDecade) / (highDecade - lowDecade) * (to - from);
        }
    }

    /** 10^k as a reader expects it: 0.001 … 10000 written out, beyond that 1e-5, 1e6. */
    static String decade(int k) {
        if (k >= 0 && k <= 4) {
            return "1" + "0".repeat(k);
        }
        if (k < 0 && k >= -3) {
            return "0." + "0".repeat(-k - 1) + "1";
        }
        return "1e" + k;
    }

    private static String line(double x1, double y1, double x2, double y2, String color, boolean dashed) {
        return String.format(Locale.ROOT, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\"%s/>\n",
                x1, y1, x2, y2, escape(color), dashed ? " stroke-dasharray=\"6 4\"" : "");
    }

    private static String dot(double x, double y, String color) {
        return String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"%s\"/>\n", x, y, escape(color));
    }

    private static String text(double x, double y, String anchor, String content, String extra) {
        return String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\"%s>%s</text>\n",
                x, y, anchor, extra.isEmpty() ? "" : " " + extra, escape(content));
    }

    static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
