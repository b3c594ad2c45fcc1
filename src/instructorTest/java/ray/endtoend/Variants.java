package ray.endtoend;

import java.awt.image.BufferedImage;
import java.lang.reflect.Field;
import java.nio.file.Path;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.function.UnaryOperator;
import ray.IntersectionRecord;
import ray.Ray;
import ray.camera.Camera;
import ray.image.Image;
import ray.image.PngWriter;
import ray.math.Vec3;
import ray.numerics.TextbookSurfaces;
import ray.numerics.TextbookTriangles;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneLoader;
import ray.shading.Light;
import ray.shading.Shader;
import ray.shading.ShadingContext;
import ray.surface.GroupSurface;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Transformed;
import ray.surface.Triangle;

/**
 * Renders of a shipped scene with the solution, changed in one way each: defects that the
 * render comparison must catch, and correct variants (other formulas, other thread counts, other
 * rounding) that it must let through. Used by {@link ToleranceTest} and {@link ToleranceSurvey}.
 */
final class Variants {
    private Variants() {
    }

    /** The scene rendered at full size by the solution, as the references are, with {@code threads} threads. */
    static BufferedImage solution(Path file, int threads) {
        Scene scene = SceneLoader.load(file);
        return PngWriter.toBufferedImage(new Renderer(scene, 0, threads).render().image, scene.getExposure());
    }

    /** Defect (a): pixel centers at (i/nx, j/ny) instead of ((i + ½)/nx, (j + ½)/ny), i.e. the image shifted by half a pixel. */
    static BufferedImage halfPixelCamera(Path file) {
        Scene scene = SceneLoader.load(file);
        scene.setCamera(new HalfPixelCamera(scene.getCamera(), scene.getWidth(), scene.getHeight()));
        return render(scene);
    }

    /** Defect (b): the correct image upside down (PNG rows written bottom first). */
    static BufferedImage flipped(BufferedImage image) {
        return ray.grading.KnownMistakes.flippedVertically(image);
    }

    /** Defect (c): shadows missing: every shader sees a shading whose shadow test always says unoccluded. */
    static BufferedImage withoutShadows(Path file) {
        Scene scene = SceneLoader.load(file);
        forEachSurface(scene.getSurfaces(), s -> {
            if (s.getShader() != null && !(s instanceof Transformed)) {
                s.setShader(new NoShadows(s.getShader()));
            }
        });
        return render(scene);
    }

    /** Correct variant: every sphere intersected by the textbook quadratic b² − 4ac, without re-projecting the hit. */
    static BufferedImage textbookSpheres(Path file) {
        Scene scene = SceneLoader.load(file);
        replacePrimitives(scene.getSurfaces(), s -> s instanceof Sphere ? TextbookSurfaces.sphere((Sphere) s) : s);
        return render(scene);
    }

    /** Correct variant: every triangle intersected by Möller–Trumbore instead of Cramer's rule. */
    static BufferedImage mollerTrumboreTriangles(Path file) {
        Scene scene = SceneLoader.load(file);
        replacePrimitives(scene.getSurfaces(), s -> s instanceof Triangle ? TextbookSurfaces.triangle((Triangle) s, TextbookTriangles.MOLLER_TRUMBORE) : s);
        return render(scene);
    }

    /**
     * Correct variant standing in for another machine's libm: each radiance channel moved by one
     * ulp up or down at random (seeded) and tone-mapped with StrictMath.pow instead of Math.pow.
     */
    static BufferedImage ulpJitter(Path file) {
        Scene scene = SceneLoader.load(file);
        Image image = new Renderer(scene, 0, 0).render().image;
        Random random = new Random(20240611L);
        double exposure = scene.getExposure();
        BufferedImage out = new BufferedImage(image.width(), image.height(), BufferedImage.TYPE_INT_RGB);
        for (int j = 0; j < image.height(); j++) {
            for (int i = 0; i < image.width(); i++) {
                Vec3 c = image.get(i, j);
                int r = strictToByte(jitter(c.x, random), exposure);
                int g = strictToByte(jitter(c.y, random), exposure);
                int b = strictToByte(jitter(c.z, random), exposure);
                out.setRGB(i, image.height() - 1 - j, r << 16 | g << 8 | b);
            }
        }
        return out;
    }

    private static double jitter(double x, Random random) {
        return random.nextBoolean() ? Math.nextUp(x) : Math.nextDown(x);
    }

    /** ToneMap.toByte with StrictMath.pow (fdlibm), the pow another JVM might effectively compute. */
    private static int strictToByte(double radiance, double exposure) {
        double x = exposure * radiance;
        if (!(x > 0)) {
            return 0;
        }
        if (x >= 1) {
            return 255;
        }
        return (int) Math.floor(255 * StrictMath.pow(x, 1 / 2.2) + 0.5);
    }

    private static BufferedImage render(Scene scene) {
        return PngWriter.toBufferedImage(new Renderer(scene, 0, 0).render().image, scene.getExposure());
    }

    /** Visits every surface of the tree once, groups and the surfaces inside transforms included. */
    private static void forEachSurface(Surface root, java.util.function.Consumer<Surface> action) {
        Set<Surface> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        java.util.ArrayDeque<Surface> work = new java.util.ArrayDeque<>(List.of(root));
        while (!work.isEmpty()) {
            Surface s = work.pop();
            if (seen.add(s)) {
                action.accept(s);
                work.addAll(s.children());
            }
        }
    }

    /** Replaces primitives inside every group's child list (read by reflection: GroupSurface keeps it protected). */
    @SuppressWarnings("unchecked")
    private static void replacePrimitives(Surface root, UnaryOperator<Surface> replacement) {
        Field field;
        try {
            field = GroupSurface.class.getDeclaredField("surfaces");
            field.setAccessible(true);
        } catch (NoSuchFieldException e) {
            throw new IllegalStateException("GroupSurface no longer keeps its children in a field named surfaces", e);
        }
        forEachSurface(root, s -> {
            if (s instanceof GroupSurface) {
                try {
                    ((List<Surface>) field.get(s)).replaceAll(replacement);
                } catch (IllegalAccessException e) {
                    throw new IllegalStateException(e);
                }
            }
        });
    }

    /** Shifts every image point by −½ pixel, so pixel (i, j) is sampled around (i/nx, j/ny). */
    static final class HalfPixelCamera extends Camera {
        private final Camera camera;
        private final int nx;
        private final int ny;

        HalfPixelCamera(Camera camera, int nx, int ny) {
            this.camera = camera;
            this.nx = nx;
            this.ny = ny;
        }

        @Override
        public Ray generateRay(double imageU, double imageV) {
            return camera.generateRay(imageU - 0.5 / nx, imageV - 0.5 / ny);
        }
    }

    /** Shades as {@code shader} does, except that no light is ever blocked. */
    static final class NoShadows extends Shader {
        private final Shader shader;

        NoShadows(Shader shader) {
            this.shader = shader;
        }

        @Override
        public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext shading, int depth) {
            return shader.shade(hit, ray, new ShadingContext() {
                @Override
                public List<Light> lights() {
                    return shading.lights();
                }

                @Override
                public boolean unoccluded(IntersectionRecord h, Vec3 lightPosition) {
                    return true;
                }

                @Override
                public Vec3 radiance(IntersectionRecord h, Vec3 direction, int d) {
                    return shading.radiance(h, direction, d);
                }
            }, depth);
        }
    }
}
