package ray.numerics;

import ray.Ray;
import ray.math.Vec3;
import ray.surface.Sphere;

/** One ray–sphere test input of the numerics catalogue, and the three intersectors that judge it. */
final class SphereCase {
    final Vec3 center;
    final double radius;
    final Ray ray;

    SphereCase(Vec3 center, double radius, Ray ray) {
        this.center = center;
        this.radius = radius;
        this.ray = ray;
    }

    /** The solution's sphere (robust: closest-approach discriminant, stable quadratic, re-projection). */
    Sphere robust() {
        return new Sphere(center, radius);
    }

    TextbookSphere textbook() {
        return new TextbookSphere(center, radius);
    }

    /** The exact hit/miss alone (no square root): for counting agreement over many rays. */
    boolean exactlyHit() {
        return ExactSphere.hits(ray, center, radius);
    }

    ExactSphere exact() {
        return ExactSphere.of(ray, center, radius);
    }

    @Override
    public String toString() {
        return "sphere " + center + " r " + radius + ", " + ray;
    }
}
