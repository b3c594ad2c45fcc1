package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int w = image.width();
        int h = image.height();
        u = u - Math.floor(u);
        v = v - Math.floor(v);
        int x = (int) Math.round(u * w + 0.5) % w;
        int y = (int) Math.round((1 - v) * h + 0.5) % h;
        return texel(x, y);
    }
}
