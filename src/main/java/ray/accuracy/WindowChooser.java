package ray.accuracy;

import ray.image.Image;
import ray.image.ToneMap;
import ray.math.Vec3;
import ray.render.PixelWindow;

/**
 * Picks the part of an image where sampling matters most: the window of a given size with the most
 * edge, measured as the summed difference of displayed values between neighboring pixels. Edges are
 * where one sample per pixel aliases, so that is where the sweep of samples per pixel has something
 * to show; a flat window would show only noise-free shading.
 */
public final class WindowChooser {
    /** Candidate windows start every STRIDE pixels (the best one is then found within STRIDE/2). */
    static final int STRIDE = 4;

    private WindowChooser() {
    }

    /**
     * The size×size window (smaller where the image is) of {@code preview} with the largest edge
     * sum; ties go to the window nearest the top left.
     */
    public static PixelWindow busiest(Image preview, double exposure, int size) {
        int w = preview.width();
        int h = preview.height();
        int ww = Math.min(size, w);
        int wh = Math.min(size, h);
        // Summed-area table of the edge measure, rows from the top as in the file: sums[y][x] is
        // the sum over rows < y and columns < x.
        double[][] sums = new double[h + 1][w + 1];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double e = edge(preview, exposure, x, y);
                sums[y + 1][x + 1] = e + sums[y][x + 1] + sums[y + 1][x] - sums[y][x];
            }
        }
        int bestX = 0;
        int bestY = 0;
        double best = -1;
        for (int y = 0; y + wh <= h; y = next(y, wh, h)) {
            for (int x = 0; x + ww <= w; x = next(x, ww, w)) {
                double s = sums[y + wh][x + ww] - sums[y][x + ww] - sums[y + wh][x] + sums[y][x];
                if (s > best) {
                    best = s;
                    bestX = x;
                    bestY = y;
                }
            }
        }
        return new PixelWindow(bestX, bestY, ww, wh);
    }

    /** The next candidate start after {@code at}: STRIDE further, and the last start that fits is always tried. */
    private static int next(int at, int size, int length) {
        int last = length - size;
        return at < last && at + STRIDE > last ? last : at + STRIDE;
    }

    /** |display difference| to the right and below neighbors, summed over the channels (file rows from the top). */
    private static double edge(Image image, double exposure, int x, int y) {
        int j = image.height() - 1 - y;
        Vec3 here = image.get(x, j);
        double sum = 0;
        if (x + 1 < image.width()) {
            sum += difference(here, image.get(x + 1, j), exposure);
        }
        if (j > 0) {
            sum += difference(here, image.get(x, j - 1), exposure);
        }
        return sum;
    }

    private static double difference(Vec3 a, Vec3 b, double exposure) {
        double sum = 0;
        for (int axis = 0; axis < 3; axis++) {
            sum += Math.abs(ToneMap.display(a.get(axis), exposure) - ToneMap.display(b.get(axis), exposure));
        }
        return sum;
    }
}
