package ray.render;

import java.util.Locale;

/**
 * A rectangle of an image's pixels: columns x … x+width−1 and rows y … y+height−1, y counted from
 * the top as in the PNG file. A render of a window traces exactly the rays those pixels get in a
 * render of the whole image, so its pixels equal that render's bit for bit.
 */
public final class PixelWindow {
    public final int x;
    public final int y;
    public final int width;
    public final int height;

    public PixelWindow(int x, int y, int width, int height) {
        if (x < 0 || y < 0 || width <= 0 || height <= 0) {
            throw new IllegalArgumentException("a window needs x, y ≥ 0 and a positive width and height, got " + describe(x, y, width, height));
        }
        this.x = x;
        this.y = y;
        this.width = width;
        this.height = height;
    }

    /** The whole of a width×height image. */
    public static PixelWindow whole(int width, int height) {
        return new PixelWindow(0, 0, width, height);
    }

    /**
     * Parses "X,Y,W,H" (Y from the top).
     *
     * @throws IllegalArgumentException with a one-line message when it is not four integers
     */
    public static PixelWindow parse(String text) {
        String[] parts = text.trim().split("\\s*,\\s*");
        if (parts.length != 4) {
            throw new IllegalArgumentException("a window is X,Y,WIDTH,HEIGHT (four integers, Y from the top), got '" + text + "'");
        }
        int[] values = new int[4];
        for (int k = 0; k < 4; k++) {
            try {
                values[k] = Integer.parseInt(parts[k]);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("a window is X,Y,WIDTH,HEIGHT (four integers, Y from the top), got '" + text + "'");
            }
        }
        return new PixelWindow(values[0], values[1], values[2], values[3]);
    }

    /** Whether this window lies inside a width×height image. */
    public boolean fitsIn(int imageWidth, int imageHeight) {
        return x + width <= imageWidth && y + height <= imageHeight;
    }

    /** The renderer's row index (from the bottom) of this window's bottom row in an image of the given height. */
    int firstRowFromBottom(int imageHeight) {
        return imageHeight - y - height;
    }

    private static String describe(int x, int y, int width, int height) {
        return String.format(Locale.ROOT, "%d,%d,%d,%d", x, y, width, height);
    }

    @Override
    public String toString() {
        return describe(x, y, width, height);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof PixelWindow && o.toString().equals(toString());
    }

    @Override
    public int hashCode() {
        return toString().hashCode();
    }
}
