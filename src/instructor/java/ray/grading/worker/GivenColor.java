package ray.grading.worker;

import ray.image.Image;
import ray.math.Vec3;
import ray.shading.Texture;

/**
 * A shader's texture on the worker's side during one shade call: the color the judge looked up at
 * the call's hit, whatever the coordinates (the student's shading asks for the color at that hit).
 */
final class GivenColor extends Texture {
    private final Vec3 color;

    GivenColor(Vec3 color) {
        super(new Image(1, 1));
        this.color = color;
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        return color;
    }

    @Override
    public String toString() {
        return "the texture's color at this hit " + color;
    }
}
