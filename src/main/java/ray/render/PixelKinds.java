package ray.render;

import ray.surface.SurfaceKind;

/**
 * What each pixel of a render shows: the {@link SurfaceKind} of the closest hit its camera rays
 * found, as the render's own intersection code (the student's spheres, triangles, groups) reported
 * it, or {@link SurfaceKind#BACKGROUND} where they found none. Made by
 * {@link Renderer#renderWithKinds()}; a plain {@link Renderer#render()} records nothing.
 *
 * <p>A pixel of several samples takes the kind most of its camera rays hit (a surface before the
 * background where the counts tie; see {@link SurfaceKind}), so an edge pixel is named by what
 * covers most of it. One camera ray per pixel (every shipped scene but the antialiased one) makes
 * that the kind of the pixel's center ray, the ray {@code ray1 trace} follows.
 *
 * <p>Pixels are counted as in the PNG the render is written to, {@link ray.image.ImageDiff} and
 * {@code ray1 trace}: x from the left, y from the <b>top</b>, over the rendered image (the plan's
 * window, when it renders part of the scene).
 */
public final class PixelKinds {
    private final int width;
    private final int height;
    /** Per pixel, row-major from the top, the kind's ordinal. Rows are written by one render thread each. */
    private final byte[] kinds;

    PixelKinds(int width, int height) {
        this.width = width;
        this.height = height;
        this.kinds = new byte[width * height];
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** The kind pixel (x, y) shows, y from the top. */
    public SurfaceKind at(int x, int y) {
        if (x < 0 || x >= width || y < 0 || y >= height) {
            throw new IndexOutOfBoundsException("pixel (" + x + ", " + y + ") is outside " + width + "x" + height);
        }
        return SurfaceKind.ofOrdinal(kinds[y * width + x]);
    }

    /** How many pixels show {@code kind}. */
    public int count(SurfaceKind kind) {
        int n = 0;
        for (byte k : kinds) {
            if (k == kind.ordinal()) {
                n++;
            }
        }
        return n;
    }

    /** Sets pixel (i, j) as the renderer counts it: j from the bottom of the rendered image. */
    void set(int i, int rowFromBottom, SurfaceKind kind) {
        kinds[(height - 1 - rowFromBottom) * width + i] = (byte) kind.ordinal();
    }
}
