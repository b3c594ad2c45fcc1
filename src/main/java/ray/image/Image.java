package ray.image;

import ray.math.Vec3;

/**
 * A picture in linear RGB radiance, stored as doubles. Pixel (i, j) counts i from the left and
 * j from the <b>bottom</b>, as the camera's image coordinates do.
 */
public final class Image {
    private final int width;
    private final int height;
    private final double[] rgb;

    public Image(int width, int height) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("image size must be positive, got " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        this.rgb = new double[3 * width * height];
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public void set(int i, int j, Vec3 color) {
        int k = index(i, j);
        rgb[k] = color.x;
        rgb[k + 1] = color.y;
        rgb[k + 2] = color.z;
    }

    public Vec3 get(int i, int j) {
        int k = index(i, j);
        return new Vec3(rgb[k], rgb[k + 1], rgb[k + 2]);
    }

    private int index(int i, int j) {
        if (i < 0 || i >= width || j < 0 || j >= height) {
            throw new IndexOutOfBoundsException("pixel (" + i + ", " + j + ") is outside " + width + "x" + height);
        }
        return 3 * (j * width + i);
    }
}
