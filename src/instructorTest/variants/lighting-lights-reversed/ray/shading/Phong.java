package ray.shading;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** The lights by index from the last, the shadow test first, and the color summed channel by channel. */
public class Phong extends PhongShader {
    public Phong() {
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        List<Light> lights = context.lights();
        Vec3 kd = diffuseColorAt(hit);
        Vec3 ks = getSpecularColor();
        Vec3 e = ray.direction.times(-1 / ray.direction.length());
        double r = 0;
        double g = 0;
        double b = 0;
        for (int i = lights.size() - 1; i >= 0; i--) {
            Light light = lights.get(i);
            if (light.getPosition().equals(hit.location) || !context.unoccluded(hit, light.getPosition())) {
                continue;
            }
            Vec3 toLight = light.getPosition().minus(hit.location);
            double r2 = toLight.dot(toLight);
            Vec3 l = toLight.times(1 / Math.sqrt(r2));
            Vec3 sum = l.plus(e);
            Vec3 h = sum.times(1 / sum.length());
            double diffuse = Math.max(0, hit.normal.dot(l));
            double specular = Math.pow(Math.max(0, hit.normal.dot(h)), getExponent());
            Vec3 intensity = light.getIntensity();
            r += (kd.x * diffuse + ks.x * specular) * intensity.x / r2;
            g += (kd.y * diffuse + ks.y * specular) * intensity.y / r2;
            b += (kd.z * diffuse + ks.z * specular) * intensity.z / r2;
        }
        return new Vec3(r, g, b);
    }
}
