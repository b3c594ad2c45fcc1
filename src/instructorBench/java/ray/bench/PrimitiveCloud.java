package ray.bench;

import java.util.Random;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Group;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * Seeded random primitives for the intersection benchmarks: N spheres or triangles scattered in the
 * cube [−10, 10]³, and rays from a point in front of the cube toward random points in it, so that
 * a ray hits a few primitives and misses most, as camera rays do. The same primitives are offered
 * as objects (a {@link Group}) and as flat arrays ({@link FlatSpheres}, {@link FlatTriangles}).
 */
final class PrimitiveCloud {
    static final int PRIMITIVES = 1000;
    static final int RAYS = 1024;
    private static final long SEED = 20261122L;

    final Surface[] surfaces;
    final Ray[] rays = new Ray[RAYS];

    private PrimitiveCloud(Surface[] surfaces, Random random) {
        this.surfaces = surfaces;
        Vec3 eye = new Vec3(0, 0, -30);
        for (int k = 0; k < RAYS; k++) {
            rays[k] = new Ray(eye, point(random).minus(eye));
        }
    }

    static PrimitiveCloud spheres() {
        Random random = new Random(SEED);
        Surface[] s = new Surface[PRIMITIVES];
        for (int k = 0; k < s.length; k++) {
            s[k] = new Sphere(point(random), 0.3 + 0.3 * random.nextDouble());
        }
        return new PrimitiveCloud(s, random);
    }

    static PrimitiveCloud triangles() {
        Random random = new Random(SEED);
        Surface[] s = new Surface[PRIMITIVES];
        for (int k = 0; k < s.length; k++) {
            Vec3 corner = point(random);
            s[k] = new Triangle(corner, corner.plus(offset(random)), corner.plus(offset(random)));
        }
        return new PrimitiveCloud(s, random);
    }

    static PrimitiveCloud of(String primitive) {
        switch (primitive) {
            case "sphere":
                return spheres();
            case "triangle":
                return triangles();
            default:
                throw new IllegalArgumentException("no such primitive: " + primitive);
        }
    }

    Group group() {
        Group group = new Group();
        for (Surface s : surfaces) {
            group.addSurface(s);
        }
        return group;
    }

    private static Vec3 point(Random random) {
        return new Vec3(20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10);
    }

    private static Vec3 offset(Random random) {
        return new Vec3(2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1);
    }
}
