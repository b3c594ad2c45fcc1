package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/**
 * Which texel a texture's own lookup reads for (u, v), by index rather than by color: the lookup
 * is asked once more on an image of the same size whose every texel holds its own column and row,
 * so the color it returns is the texel's address. Matching colors in the real image cannot do
 * this: many texels share a color (a flat sea, a black sky), and the first match found is often not
 * the texel the code read. The texture's image is swapped for the index image during the call and
 * put back before this returns; the trace calls it on one thread, between renders.
 */
public final class TexelPick {
    /** The third channel of every index texel: no texel of a file has it (they are 0 … 1). */
    private static final double MARK = -7.25;

    private TexelPick() {
    }

    /**
     * The texel {@code texture.getTexColor(u, v)} reads, as {column, row} with the row counted from
     * the image's top (as {@link Texture#texel} counts it), or null when the lookup returns no texel
     * of the image (a color it made up, such as the stub's black) or throws.
     */
    public static int[] of(Texture texture, double u, double v) {
        Image real = texture.image;
        if (real == null) {
            return null;
        }
        int width = real.width();
        int height = real.height();
        texture.image = indices(width, height);
        Vec3 picked;
        try {
            picked = texture.getTexColor(u, v);
        } catch (RuntimeException e) {
            return null;
        } finally {
            texture.image = real;
        }
        if (picked == null || picked.z != MARK || picked.x != Math.rint(picked.x) || picked.y != Math.rint(picked.y)
                || picked.x < 0 || picked.x >= width || picked.y < 0 || picked.y >= height) {
            return null;
        }
        return new int[] {(int) picked.x, (int) picked.y};
    }

    /** A width × height image whose texel (column, row from the top) is (column, row, MARK). */
    private static Image indices(int width, int height) {
        Image image = new Image(width, height);
        for (int row = 0; row < height; row++) {
            for (int column = 0; column < width; column++) {
                // Image.set counts rows from the bottom.
                image.set(column, height - 1 - row, new Vec3(column, row, MARK));
            }
        }
        return image;
    }
}
