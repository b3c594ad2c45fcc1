package ray.shading;

import ray.IntersectionRecord;
import ray.math.Vec3;

/**
 * What the framework asks of every texture besides its lookup: that the scene gave it an image,
 * and its color at a hit. {@link Texture} implements it, so that the classes students open hold
 * only the texture's data and the method they write.
 */
public interface FrameworkTexture {
    /** Checks that an image was given. */
    default void complete() {
        if (((Texture) this).getImage() == null) {
            throw new IllegalArgumentException("no <image> is given; expected <image> with the path of an image file");
        }
    }

    /**
     * The texture's color at a hit. The coordinates are rounded to float first, as the course's
     * renderer passes them, so that a coordinate at a texel's edge rounds the same way here.
     */
    default Vec3 colorAt(IntersectionRecord hit) {
        return ((Texture) this).getTexColor((float) hit.texU, (float) hit.texV);
    }
}
