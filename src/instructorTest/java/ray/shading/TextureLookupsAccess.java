package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** {@link TextureLookups} for graded tests in other packages (the hidden tests). */
public final class TextureLookupsAccess {
    private static final String REPEAT = "a RepeatTexture wraps column (int)(u·W + 0.5) and row (int)((1 − v)·H + 0.5),"
            + " counted from the top (Math.floor instead of (int) is accepted too), into the image";
    private static final String CLAMP = "a ClampTexture clamps column (int)(u·W + 0.5) and row (int)((1 − v)·H + 0.5),"
            + " counted from the top (Math.floor instead of (int) is accepted too), to the image";

    private TextureLookupsAccess() {
    }

    public static Image distinctTexels(int width, int height) {
        return TextureLookups.distinctTexels(width, height);
    }

    /** Texel (column, row) of a distinctTexels image, the row counted from the top. */
    public static Vec3 texel(int width, int height, int column, int row) {
        return TextureLookups.texel(width, height, column, row);
    }

    public static void assertRepeat(Texture texture, int width, int height, double u, double v) {
        TextureLookups.assertLookup(REPEAT, texture, width, height, u, v, i -> Math.floorMod(i, width), r -> Math.floorMod(r, height));
    }

    public static void assertClamp(Texture texture, int width, int height, double u, double v) {
        TextureLookups.assertLookup(CLAMP, texture, width, height, u, v, i -> Math.max(0, Math.min(width - 1, i)),
                r -> Math.max(0, Math.min(height - 1, r)));
    }

    /** Checks that the lookup at (u, v) is exactly texel (column, row) of a distinctTexels image. */
    public static void assertTexel(Texture texture, int width, int height, double u, double v, int column, int row) {
        TextureLookups.assertTexel(texture instanceof ClampTexture ? CLAMP : REPEAT, texture, width, height, u, v, column, row);
    }
}
