package ray.shading;

import java.nio.file.Path;
import ray.IntersectionRecord;
import ray.image.Image;
import ray.image.TextureFiles;
import ray.math.Vec3;

/**
 * An image wrapped onto surfaces by texture coordinates: (u, v) = (0, 0) is the image's bottom-left
 * corner and (1, 1) its top-right. A subclass decides what lies outside [0, 1]² (the student's
 * {@link RepeatTexture} and {@link ClampTexture}).
 *
 * <p>Lookups take the texel the course's reference renderer takes. With W × H texels, counted as
 * image files count them (columns from the left, rows from the top), the column is
 * i = (int) (u·W + 0.5) and the row is (int) ((1 − v)·H + 0.5): v counts up from the bottom, rows
 * down from the top, so v is turned into a distance from the top, 1 − v, <em>before</em> it is
 * scaled and rounded. Texel (i, row) then covers the coordinates within half a texel of
 * (u, 1 − v) = (i/W, row/H). Flipping after the rounding instead, row H − 1 − (int) (v·H + 0.5),
 * lands one row higher everywhere: the two differ by one row at every v, not only at the edges.
 * Rounding down with Math.floor instead of the cast is as right: it differs only where the value
 * rounded is negative, by one texel, which a clamp removes and the tests accept.
 * {@link #texel(int, int)} reads a texel by that column and row. (What the framework asks of a
 * texture besides, its check and its color at a hit, is in {@link FrameworkTexture}.)
 */
public abstract class Texture implements FrameworkTexture {
    /**
     * The texels, each the file's 8-bit color / 255; set by setImage. {@code image.get(i, j)} counts j
     * from the bottom, as rendered images do; lookups use {@link #texel(int, int)}, which counts rows
     * from the top, as image files do.
     */
    protected Image image;

    protected Texture() {
    }

    /** A texture of texels made in code (tests, generated textures). */
    protected Texture(Image image) {
        this.image = image;
    }

    /** Reads the texture's image file (from the scene's {@code <image>}, relative to the scene file). */
    public void setImage(Path file) {
        this.image = TextureFiles.read(file);
    }

    public Image getImage() {
        return image;
    }

    /**
     * The color of texel ({@code column}, {@code row}) of the image: the column counted from the
     * image's left (0 … W − 1), the row from its top (0 … H − 1), as image files and the course
     * count them; each component is the file's 8-bit value / 255.
     *
     * @throws IndexOutOfBoundsException if the column or row is outside the image
     */
    protected final Vec3 texel(int column, int row) {
        int width = image.width();
        int height = image.height();
        if (column < 0 || column >= width || row < 0 || row >= height) {
            throw new IndexOutOfBoundsException("texel (" + column + ", " + row + ") is outside the " + width + "×" + height
                    + " image; expected a column in 0…" + (width - 1) + " and a row in 0…" + (height - 1));
        }
        return image.get(column, height - 1 - row);
    }

    /**
     * The color of the texel the course's rule picks for (u, v): each component the texel's 8-bit value / 255.
     * Coordinates outside [0, 1] repeat or clamp, as the subclass says. Never null; NaN coordinates
     * give some texel of the image.
     */
    public abstract Vec3 getTexColor(double u, double v);

    @Override
    public String toString() {
        return getClass().getSimpleName() + (image == null ? "[no image]" : "[" + image.width() + "×" + image.height() + "]");
    }
}
