package ray.render;

import static ray.testing.Asserts.v;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.surface.Sphere;
import ray.surface.Triangle;

/**
 * A 20×10 scene whose pixels can be counted by hand: an orthographic camera at (0, 0, 10) looking
 * down −z at x in [−10, 10], y in [−5, 5], one unit per pixel, so pixel (x, y) (y from the top, as
 * in the PNG) sees the point (x − 9.5, 4.5 − y). On the left a sphere of radius 3.5 at (−5, 0, 0);
 * on the right, in the plane z = 0, the triangle (1, −4), (9.25, −4), (1, 4.25), both Lambertian,
 * lit by one light 2 above (1.5, 0.5) on a dark blue background.
 *
 * <p>Hand counts. The triangle covers the pixel centers x − 9.5 = 1.5 + a, 4.5 − y = −3.5 + b with
 * a, b ≥ 0 and (a + ½) + (b + ½) &lt; 8.25, i.e. a + b ≤ 7 (no center lies on an edge): 8 + 7 + … + 1
 * = {@value #TRIANGLE_PIXELS} pixels, columns 11 to 18. Its β (the weight of (9.25, −4)) is
 * (a + ½)/8.25, above ½ for a ≥ 4: 4 + 3 + 2 + 1 = {@value #TRIANGLE_PIXELS_BETA_ABOVE_HALF} of them.
 * The sphere covers the centers ½(m, n) from (−5, 0) with m, n odd and m² + n² &lt; 49: 12 with |m| = 1,
 * 12 with |m| = 3, 8 with |m| = 5, {@value #SPHERE_PIXELS} in all (none on the rim, where m² + n²
 * would be 49). The brightest triangle pixel is the one right under the light, (11, 4): L = kd·I/2²
 * = 0.75, 224 in 8 bits; its neighbours are 2/√5·0.75/1.25 ≈ 0.537 (192).
 */
public final class SphereAndTriangle {
    public static final int WIDTH = 20;
    public static final int HEIGHT = 10;
    public static final int TRIANGLE_PIXELS = 36;
    public static final int TRIANGLE_PIXELS_BETA_ABOVE_HALF = 10;
    public static final int SPHERE_PIXELS = 32;

    private SphereAndTriangle() {
    }

    /** How a variant makes its triangle from the three vertices. */
    public interface TriangleMaker {
        Triangle make(Vec3 v0, Vec3 v1, Vec3 v2);
    }

    /** The scene with the solution's triangle. */
    public static Scene scene() {
        return scene(Triangle::new);
    }

    /** The scene with its triangle made by {@code maker}. */
    public static Scene scene(TriangleMaker maker) {
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 10), WIDTH, HEIGHT), WIDTH, HEIGHT);
        // No grey is within 2 levels of it in every channel, so a pixel that loses a surface always differs.
        scene.setBackColor(v(0, 0, 0.3));
        scene.addLight(new Light(v(1.5, 0.5, 2), v(6, 6, 6)));
        Sphere sphere = new Sphere(v(-5, 0, 0), 3.5);
        sphere.setShader(new Lambertian(v(0.5, 0.5, 0.5)));
        scene.addSurface(sphere.complete());
        Triangle triangle = maker.make(v(1, -4, 0), v(9.25, -4, 0), v(1, 4.25, 0));
        triangle.setShader(new Lambertian(v(0.5, 0.5, 0.5)));
        scene.addSurface(triangle.complete());
        scene.complete();
        return scene;
    }

    /** A wrong triangle: it reports the inward normal, so its lit side shades black; it covers the same pixels. */
    public static final class NormalFlipped extends Triangle {
        public NormalFlipped(Vec3 v0, Vec3 v1, Vec3 v2) {
            super(v0, v1, v2);
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            if (!super.intersect(out, ray)) {
                return false;
            }
            out.normal = out.normal.negate();
            return true;
        }
    }

    /** A wrong triangle: it misses wherever β &gt; ½, so part of it shows the background. */
    public static class HalfMissing extends Triangle {
        public HalfMissing(Vec3 v0, Vec3 v1, Vec3 v2) {
            super(v0, v1, v2);
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            IntersectionRecord hit = new IntersectionRecord();
            if (!super.intersect(hit, ray) || hit.beta > 0.5) {
                return false;
            }
            out.set(hit);
            return true;
        }
    }

    /** Both mistakes: the part it keeps is black, the rest shows the background. */
    public static final class HalfMissingNormalFlipped extends HalfMissing {
        public HalfMissingNormalFlipped(Vec3 v0, Vec3 v1, Vec3 v2) {
            super(v0, v1, v2);
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            if (!super.intersect(out, ray)) {
                return false;
            }
            out.normal = out.normal.negate();
            return true;
        }
    }
}
