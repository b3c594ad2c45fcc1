package ray.inspect;

import ray.scene.Scene;

/**
 * Pixel (x, y) as an image viewer counts it (x from the left, y from the top) in the renderer's
 * terms: (i, j) with j from the bottom, and the image point (u, v) of its center,
 * ((i + ½)/width, (j + ½)/height).
 */
final class PixelCoordinates {
    final int i;
    final int j;
    final double u;
    final double v;

    PixelCoordinates(Scene scene, int x, int y) {
        i = x;
        j = scene.getHeight() - 1 - y;
        u = (i + 0.5) / scene.getWidth();
        v = (j + 0.5) / scene.getHeight();
    }
}
