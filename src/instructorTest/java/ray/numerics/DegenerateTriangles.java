package ray.numerics;

import java.util.Random;
import ray.math.Vec3;
import ray.surface.Triangle;

/**
 * Seeded triangles without area, the kinds a mesh file or a careless generator produces, each
 * exactly degenerate in double: collinear (integer points on an integer line, so every coordinate
 * and every cross product is exact), two vertices equal, all three equal, and a vertex with a NaN
 * or infinite coordinate. {@link #target} is a point of the triangle's segment (or point) for rays
 * to aim at.
 */
final class DegenerateTriangles {
    static final String[] KINDS = {"collinear", "two vertices equal", "all three equal", "non-finite vertex"};
    private static final double[] NON_FINITE = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};

    private final Random random;
    /** The kind (an index into KINDS) and a point on the triangle, of the last one made. */
    int kind;
    Vec3 target;

    DegenerateTriangles(long seed) {
        this.random = new Random(seed);
    }

    /**
     * Whether complete() found the triangle degenerate, which it shows by a zero face normal. (Tests
     * ask this rather than a new accessor, so that they still compile against an older student copy
     * of Triangle.java when the grader builds the whole tree.)
     */
    static boolean hasNoArea(Triangle t) {
        return t.getFaceNormal().lengthSquared() == 0;
    }

    /** The next triangle, cycling through the kinds. */
    Triangle next(int index) {
        kind = index % KINDS.length;
        Vec3 a = integerPoint(100);
        switch (kind) {
            case 0: {
                Vec3 e;
                do {
                    e = integerPoint(5);
                } while (e.lengthSquared() == 0);
                int k1 = random.nextInt(21) - 10;
                int k2 = random.nextInt(21) - 10;
                Vec3 b = a.plus(e.times(k1));
                Vec3 c = a.plus(e.times(k2));
                // A point between two of the three, on the line in exact arithmetic (rounded here).
                target = a.plus(b.minus(a).times(random.nextDouble()));
                return shuffled(a, b, c);
            }
            case 1: {
                Vec3 b = randomPoint(100);
                target = a.plus(b.minus(a).times(random.nextDouble()));
                return shuffled(a, a, b);
            }
            case 2:
                target = a;
                return new Triangle(a, a, a);
            default: {
                Vec3 b = randomPoint(100);
                Vec3 c = randomPoint(100);
                target = a.plus(b).plus(c).times(1.0 / 3);
                double bad = NON_FINITE[random.nextInt(3)];
                int axis = random.nextInt(3);
                Vec3 broken = new Vec3(axis == 0 ? bad : c.x, axis == 1 ? bad : c.y, axis == 2 ? bad : c.z);
                return shuffled(a, b, broken);
            }
        }
    }

    /** The three vertices in one of their six orders. */
    private Triangle shuffled(Vec3 a, Vec3 b, Vec3 c) {
        Vec3[] v = {a, b, c};
        for (int i = 2; i > 0; i--) {
            int j = random.nextInt(i + 1);
            Vec3 swap = v[i];
            v[i] = v[j];
            v[j] = swap;
        }
        return new Triangle(v[0], v[1], v[2]);
    }

    private Vec3 integerPoint(int extent) {
        return new Vec3(random.nextInt(2 * extent + 1) - extent, random.nextInt(2 * extent + 1) - extent,
                random.nextInt(2 * extent + 1) - extent);
    }

    private Vec3 randomPoint(double extent) {
        return new Vec3(extent * (2 * random.nextDouble() - 1), extent * (2 * random.nextDouble() - 1),
                extent * (2 * random.nextDouble() - 1));
    }
}
