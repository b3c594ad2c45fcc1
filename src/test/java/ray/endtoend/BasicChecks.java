package ray.endtoend;

import java.util.EnumSet;
import java.util.Set;
import java.util.function.Supplier;
import ray.IntersectionRecord;
import ray.Ray;
import ray.camera.Camera;
import ray.camera.OrthographicCamera;
import ray.camera.PerspectiveCamera;
import ray.image.Image;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.ClampTexture;
import ray.shading.RepeatTexture;
import ray.shading.Texture;
import ray.surface.Cylinder;
import ray.surface.FixedHitSurface;
import ray.surface.Group;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;
import ray.surface.TriangleSet;
import ray.testing.StudentTask;

/**
 * Which tasks a scene's render runs, and one plain check per task that any finished solution
 * passes (a ray straight at a sphere hits it, a group reports its one hit, ...), so that a render
 * test that fails can say whether its own task or another, unfinished one is to blame.
 *
 * <p>These checks never decide a grade: a render test passes or fails by its image alone, and the
 * checks only choose the words of a failure. Each expects what the task's contract promises and
 * nothing more (a ray's direction may have any length; hits are compared with a tolerance).
 */
final class BasicChecks {
    private BasicChecks() {
    }

    /** The tasks whose code renders {@code scene}: the camera and the group always, and each primitive or texture it holds. */
    static Set<StudentTask> tasksOf(Scene scene) {
        Set<StudentTask> tasks = EnumSet.of(StudentTask.CAMERA, StudentTask.GROUP);
        addTasksOf(scene.getSurfaces(), tasks);
        if (!scene.getTextures().isEmpty()) {
            tasks.add(StudentTask.TEXTURE);
        }
        return tasks;
    }

    private static void addTasksOf(Surface surface, Set<StudentTask> tasks) {
        if (surface instanceof Sphere) {
            tasks.add(StudentTask.SPHERE);
        } else if (surface instanceof Triangle || surface instanceof TriangleSet) {
            tasks.add(StudentTask.TRIANGLE);
        } else if (surface instanceof Cylinder) {
            tasks.add(StudentTask.CYLINDER);
        }
        for (Surface child : surface.children()) {
            addTasksOf(child, tasks);
        }
    }

    /** What the task's code gets wrong in its plain check, or null when the check passes. */
    static String problem(StudentTask task, Scene scene) {
        try {
            switch (task) {
                case CAMERA:
                    return cameraProblem(scene.getCamera());
                case SPHERE:
                    return hitProblem("Sphere.intersect", "a unit sphere 5 units ahead of the ray", new Sphere(Vec3.ZERO, 1), 4);
                case TRIANGLE:
                    return hitProblem("Triangle.intersect", "a triangle 5 units straight ahead of the ray",
                            new Triangle(new Vec3(-1, -1, 0), new Vec3(1, -1, 0), new Vec3(0, 1, 0)), 5);
                case GROUP:
                    return groupProblem();
                case TEXTURE:
                    return textureProblem();
                case CYLINDER:
                    return hitProblem("Cylinder.intersect", "the top cap of a cylinder straight below the ray (direction (0, −2, 0))",
                            new Cylinder(new Vec3(0, -3, 0), 1, 2), 2, new Ray(new Vec3(0, 3, 0), new Vec3(0, -2, 0)));
                default:
                    return null;
            }
        } catch (RuntimeException | StackOverflowError e) {
            return "it throws " + e;
        }
    }

    /** The ray through the image's center must look along viewDir from viewPoint, and the one through its upper-right corner up and to the right. */
    private static String cameraProblem(Camera sceneCamera) {
        Camera camera;
        if (sceneCamera instanceof OrthographicCamera) {
            camera = new OrthographicCamera();
        } else if (sceneCamera instanceof PerspectiveCamera) {
            camera = new PerspectiveCamera();
        } else {
            return null;
        }
        String name = camera.getClass().getSimpleName() + ".generateRay";
        camera.setViewWidth(2);
        camera.setViewHeight(2);
        camera.complete();
        // The default view: from the origin along −z, y up, so u = +x, v = +y; the image plane is 2 × 2 (1 unit away).
        Ray center = camera.generateRay(0.5, 0.5);
        String problem = emptyRayProblem(name, center);
        if (problem != null) {
            return problem;
        }
        if (!close(center.origin, Vec3.ZERO) || !sameDirection(center.direction, new Vec3(0, 0, -1))) {
            return name + "(0.5, 0.5) of a camera at the origin looking along −z returned origin " + center.origin
                    + ", direction " + center.direction + "; expected origin (0, 0, 0) and a direction along (0, 0, −1)";
        }
        Ray corner = camera.generateRay(1, 1);
        problem = emptyRayProblem(name, corner);
        if (problem != null) {
            return problem;
        }
        boolean orthographic = camera instanceof OrthographicCamera;
        Vec3 origin = orthographic ? new Vec3(1, 1, 0) : Vec3.ZERO;
        Vec3 direction = orthographic ? new Vec3(0, 0, -1) : new Vec3(1, 1, -1);
        if (!close(corner.origin, origin) || !sameDirection(corner.direction, direction)) {
            return name + "(1, 1), the upper-right corner of a 2 × 2 image plane, returned origin " + corner.origin
                    + ", direction " + corner.direction + "; expected origin " + origin + " and a direction along " + direction;
        }
        return null;
    }

    private static String emptyRayProblem(String name, Ray ray) {
        if (ray == null || ray.origin == null || ray.direction == null) {
            return name + " returned " + (ray == null ? "null" : "a ray without an origin or a direction");
        }
        if (!(ray.start < ray.end) || ray.direction.lengthSquared() == 0) {
            return name + " returned a ray that cannot reach anything (start " + ray.start + ", end " + ray.end
                    + ", direction " + ray.direction + "): is it still the stub?";
        }
        return null;
    }

    private static String hitProblem(String method, String what, Surface surface, double expectedT) {
        return hitProblem(method, what, surface, expectedT, new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1)));
    }

    private static String hitProblem(String method, String what, Surface surface, double expectedT, Ray ray) {
        Surface completed = surface.complete();
        IntersectionRecord out = new IntersectionRecord();
        if (!completed.intersect(out, ray)) {
            return method + " misses " + what + " (expected a hit at t = " + expectedT + ")";
        }
        if (Math.abs(out.t - expectedT) > 1e-9 * expectedT) {
            return method + " hits " + what + " at t = " + out.t + "; expected t = " + expectedT;
        }
        return null;
    }

    private static String groupProblem() {
        Group group = new Group();
        group.addSurface(new FixedHitSurface("far", 7, new Vec3(0, 0, 1)));
        group.addSurface(new FixedHitSurface("near", 3, new Vec3(0, 0, 1)));
        IntersectionRecord out = new IntersectionRecord();
        if (!group.intersect(out, new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1)))) {
            return "Group.intersect finds no hit in a group of two surfaces that are both hit";
        }
        if (out.t != 3) {
            return "Group.intersect reports t = " + out.t + " for two surfaces hit at t = 7 and t = 3; expected the closer, t = 3";
        }
        return null;
    }

    /**
     * A 2 × 2 texture of four colors: the lookup at each texel's center (u = column / 2 and
     * v = 1 − row / 2, the row counted from the top) must give that texel.
     */
    private static String textureProblem() {
        Image image = new Image(2, 2);
        for (int i = 0; i < 2; i++) {
            for (int j = 0; j < 2; j++) {
                image.set(i, j, new Vec3(i, j, 0.5)); // j counts from the bottom
            }
        }
        for (Supplier<Texture> make : java.util.List.<Supplier<Texture>>of(() -> new RepeatTexture(image), () -> new ClampTexture(image))) {
            Texture texture = make.get();
            for (int column = 0; column < 2; column++) {
                for (int row = 0; row < 2; row++) {
                    double u = 0.5 * column;
                    double v = 1 - 0.5 * row;
                    Vec3 expected = image.get(column, 1 - row);
                    Vec3 color = texture.getTexColor(u, v);
                    if (color == null || !close(color, expected)) {
                        return texture.getClass().getSimpleName() + ".getTexColor(" + u + ", " + v + ") on a 2 × 2 image returned "
                                + color + "; expected texel (" + column + ", " + row + ") counted from the top-left, " + expected;
                    }
                }
            }
        }
        return null;
    }

    private static boolean close(Vec3 a, Vec3 b) {
        return a.minus(b).length() <= 1e-9;
    }

    private static boolean sameDirection(Vec3 d, Vec3 expected) {
        return d.isFinite() && d.lengthSquared() > 0 && d.normalized().minus(expected.normalized()).length() <= 1e-9;
    }
}
