package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int w = image.width();
        int h = image.height();
        int x = (int) (u * w + 0.5);
        int y = (int) ((1 - v) * h + 0.5);
        x = Math.max(0, Math.min(w, x));
        y = Math.max(0, Math.min(h, y));
        return texel(x, y);
    }
}
