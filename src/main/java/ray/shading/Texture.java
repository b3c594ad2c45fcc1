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
 * <p>Lookups take the nearest texel as the course's reference renderer does: with W × H texels,
 * column i = (int) (u·W + 0.5) and row j = (int) (v·H + 0.5), so texel (i, j) covers the
 * coordinates within half a texel of (i/W, j/H). {@code image.get(i, j)} counts j from the bottom
 * row, so no flip is needed.
 */
public abstract class Texture {
    /** The texels, j counting from the bottom, each the file's 8-bit color / 255; set by setImage. */
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

    /** Checks that an image was given. */
    public void complete() {
        if (image == null) {
            throw new IllegalArgumentException("no <image> is given; expected <image> with the path of an image file");
        }
    }

    /**
     * The color of the texel nearest to (u, v): each component the texel's 8-bit value / 255.
     * Coordinates outside [0, 1] repeat or clamp, as the subclass says. Never null; NaN coordinates
     * give some texel of the image.
     */
    public abstract Vec3 getTexColor(double u, double v);

    /**
     * The texture's color at a hit. The coordinates are rounded to float first, as the course's
     * renderer passes them, so that a coordinate at a texel's edge rounds the same way here.
     */
    public final Vec3 colorAt(IntersectionRecord hit) {
        return getTexColor((float) hit.texU, (float) hit.texV);
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + (image == null ? "[no image]" : "[" + image.width() + "×" + image.height() + "]");
    }
}
