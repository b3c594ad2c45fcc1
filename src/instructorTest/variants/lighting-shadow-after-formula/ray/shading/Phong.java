package ray.shading;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Each light's share worked out first, then kept only if its shadow test passes; the half vector from l − d̂. */
public class Phong extends PhongShader {
    public Phong() {
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        Vec3 color = Vec3.ZERO;
        Vec3 d = ray.direction.normalized();
        for (Light light : context.lights()) {
            Vec3 toLight = light.getPosition().minus(hit.location);
            double distance = toLight.length();
            if (distance == 0) {
                continue;
            }
            Vec3 l = toLight.times(1 / distance);
            Vec3 h = l.minus(d).normalized();
            Vec3 diffuse = diffuseColorAt(hit).times(Math.max(0, hit.normal.dot(l)));
            Vec3 specular = getSpecularColor().times(Math.pow(Math.max(0, hit.normal.dot(h)), getExponent()));
            Vec3 share = diffuse.plus(specular).times(light.getIntensity()).times(1 / (distance * distance));
            if (context.unoccluded(hit, light.getPosition())) {
                color = color.plus(share);
            }
        }
        return color;
    }
}
