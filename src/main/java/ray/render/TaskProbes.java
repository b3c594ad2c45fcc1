package ray.render;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Hittable;
import ray.assignment.Assignment;
import ray.assignment.Task;
import ray.assignment.TaskTable;
import ray.bvh.BoundingBoxes;
import ray.bvh.Box;
import ray.bvh.BrokenTree;
import ray.bvh.BvhNode;
import ray.bvh.StudentBvh;
import ray.camera.Camera;
import ray.camera.OrthographicCamera;
import ray.camera.PerspectiveCamera;
import ray.image.Image;
import ray.math.Bounds;
import ray.math.Vec3;
import ray.shading.BeckmannDistribution;
import ray.shading.Brdf;
import ray.shading.ClampTexture;
import ray.shading.DirectLighting;
import ray.shading.Fresnel;
import ray.shading.GgxDistribution;
import ray.shading.Lambertian;
import ray.shading.LambertianBrdf;
import ray.shading.LambertianBrdfFormula;
import ray.shading.Light;
import ray.shading.MicrofacetBrdf;
import ray.shading.MicrofacetDistribution;
import ray.shading.Phong;
import ray.shading.PhongBrdf;
import ray.shading.ReflectionShader;
import ray.shading.RepeatTexture;
import ray.shading.Shader;
import ray.shading.ShadingContext;
import ray.shading.Texture;
import ray.surface.Cylinder;
import ray.surface.Group;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * One probe per class of student code, each a tiny hand-made case run on that class alone (a ray
 * straight at a unit sphere, a group of two surfaces that are both hit, a 2 × 2 texture, ...). A
 * probe tells two things apart:
 * <ul>
 * <li>whether the class still behaves as the handout's stub: every case gets the stub's answer (a
 * camera's rays that cannot reach anything, a surface or group that is never hit, a texture that is
 * black everywhere), which {@code ray1 render} reports in one line ({@link #stubs}, {@link #stillStubsLine});
 * <li>what the class gets wrong in the plain case, which any finished solution passes (the render
 * tests' basic checks, which say whether another, unfinished task is to blame for a wrong image).
 * </ul>
 * Stubs are found by what the code does, not by reading sources: the student part is plain Java and
 * ray1 may run from anywhere. Code that throws is written, only broken: never a stub.
 */
public final class TaskProbes {
    /**
     * The classes a student may fill in, one probe each. Each one's task and file come from the table
     * of tasks; a class of a task the assignment does not choose ships solved, and is never probed.
     */
    public enum Part {
        PERSPECTIVE_CAMERA("PerspectiveCamera"),
        ORTHOGRAPHIC_CAMERA("OrthographicCamera"),
        RAY_TRACER("RayTracer"),
        SPHERE("Sphere"),
        TRIANGLE("Triangle"),
        GROUP("Group"),
        REPEAT_TEXTURE("RepeatTexture"),
        CLAMP_TEXTURE("ClampTexture"),
        LAMBERTIAN("Lambertian"),
        PHONG("Phong"),
        LAMBERTIAN_BRDF("LambertianBrdf"),
        PHONG_BRDF("PhongBrdf"),
        REFLECTION_SHADER("ReflectionShader"),
        BECKMANN_DISTRIBUTION("BeckmannDistribution"),
        GGX_DISTRIBUTION("GgxDistribution"),
        FRESNEL("Fresnel"),
        MICROFACET_BRDF("MicrofacetBrdf"),
        CYLINDER("Cylinder"),
        BOUNDING_BOXES("BoundingBoxes"),
        BVH_TREE("BvhTree");

        /** Its task's id in the table. */
        public final String taskId;
        public final String className;
        /** The file to edit, relative to the project folder. */
        public final String file;

        Part(String className) {
            Task owner = TaskTable.standard().ofStudentClass(className)
                    .orElseThrow(() -> new IllegalStateException(className + " is in no task's files in " + TaskTable.PROJECT_FILE));
            this.taskId = owner.id();
            this.className = className;
            this.file = owner.projectFiles().get(owner.classNames().indexOf(className));
        }

        /** Its task's number in this assignment, or 0 when the task ships solved. */
        public int task() {
            return Assignment.current().number(taskId);
        }

        /** Whether students write it in this assignment. */
        public boolean isStudents() {
            return task() > 0;
        }
    }

    /** How long {@link #stubs()} waits for the probes: code that has not answered by then is no stub (the stubs answer at once). */
    public static final long DEFAULT_LIMIT_MILLIS = 3000;

    /** What a probe found. */
    public static final class Finding {
        /** Whether every case got the handout stub's answer. */
        public final boolean stub;
        /** What the code gets wrong in the plain case, or null when it passes it. */
        public final String problem;

        Finding(boolean stub, String problem) {
            this.stub = stub;
            this.problem = problem;
        }

        @Override
        public String toString() {
            return stub ? "stub: " + problem : problem == null ? "passes" : problem;
        }
    }

    private TaskProbes() {
    }

    /** Runs the probe of {@code part} in this thread. Whatever the student code throws becomes the problem "it throws …". */
    public static Finding probe(Part part) {
        try {
            switch (part) {
                case PERSPECTIVE_CAMERA:
                    // The upper-right corner's ray: from the eye through (1, 1, −1) on the plane one unit away.
                    return camera(new PerspectiveCamera(), Vec3.ZERO, new Vec3(1, 1, -1));
                case ORTHOGRAPHIC_CAMERA:
                    // The upper-right corner's ray: from that corner of the view, (1, 1, 0), straight ahead.
                    return camera(new OrthographicCamera(), new Vec3(1, 1, 0), new Vec3(0, 0, -1));
                case RAY_TRACER:
                    return rayTracer();
                case SPHERE:
                    return sphere();
                case TRIANGLE:
                    return triangle();
                case GROUP:
                    return group();
                case REPEAT_TEXTURE:
                    return texture(RepeatTexture::new);
                case CLAMP_TEXTURE:
                    return texture(ClampTexture::new);
                case CYLINDER:
                    return cylinder();
                case BOUNDING_BOXES:
                    return boundingBoxes();
                case BVH_TREE:
                    return bvhTree();
                case LAMBERTIAN:
                    // kd ⊙ I · (n·l) / r² = (0.5, 0.25, 1) · 4 · 1 / 4.
                    return lighting(new Lambertian(), new Vec3(0.5, 0.25, 1));
                case PHONG:
                    // (kd · (n·l) + ks · (n·h)^p) ⊙ I / r², with l = e = h = n: kd + ks.
                    Phong phong = new Phong();
                    phong.setSpecularColor(new Vec3(1, 1, 1));
                    phong.setExponent(10);
                    return lighting(phong, new Vec3(1.5, 1.25, 2));
                case LAMBERTIAN_BRDF:
                    // ρd/π, whatever the directions.
                    return brdf(new LambertianBrdf(), new Vec3(0.5 / Math.PI, 0.25 / Math.PI, 1 / Math.PI));
                case PHONG_BRDF:
                    // ρd/π + ks · (n·h)^p with l = v = h = n: ρd/π + ks.
                    return brdf(new PhongBrdf(new Vec3(1, 1, 1), 10), new Vec3(0.5 / Math.PI + 1, 0.25 / Math.PI + 1, 1 / Math.PI + 1));
                case REFLECTION_SHADER:
                    // f ⊙ I · (n·l) / r² = ρd/π · 4 · 1 / 4 with a BRDF of the probe's own (the Lambertian's
                    // formula, so that a stub of that task does not make this one look like a stub), no mirror term.
                    return lighting(new ReflectionShader("probe", new ProbeBrdf(), new Vec3(0.5, 0.25, 1), null, Vec3.ZERO, null, null),
                            new Vec3(0.5 / Math.PI, 0.25 / Math.PI, 1 / Math.PI));
                case BECKMANN_DISTRIBUTION:
                    return distribution(new BeckmannDistribution(0.5));
                case GGX_DISTRIBUTION:
                    return distribution(new GgxDistribution(0.5));
                case FRESNEL:
                    return fresnel();
                case MICROFACET_BRDF:
                    // Light and eye along n: h = n, F = R0 = 0.04 (nt 1.5), D = 1/(πα²), G1 = 1, so
                    // f = ρd/π + k_mf · 0.04/(4π · 0.25) = ρd/π + 0.04/π.
                    return brdf(new MicrofacetBrdf(Vec3.ONE, MicrofacetDistribution.GGX, 0.5, 1.5),
                            new Vec3(0.54 / Math.PI, 0.29 / Math.PI, 1.04 / Math.PI));
                default:
                    throw new AssertionError(part);
            }
        } catch (Throwable e) { // student code: anything it throws (an Error too) means written, but broken
            return new Finding(false, "it throws " + e);
        }
    }

    /** The parts that still behave as the handout's stubs, within {@link #DEFAULT_LIMIT_MILLIS}. */
    public static Set<Part> stubs() {
        return stubs(DEFAULT_LIMIT_MILLIS);
    }

    /**
     * The parts that still behave as the handout's stubs. Each probe runs in a daemon thread of its
     * own, so that student code that never returns (a loop that does not end) costs at most
     * {@code limitMillis} and stops nothing: a probe that has not answered by then counts as no stub.
     */
    public static Set<Part> stubs(long limitMillis) {
        Map<Part, Finding> found = new ConcurrentHashMap<>();
        Map<Part, Thread> threads = new EnumMap<>(Part.class);
        for (Part part : Part.values()) {
            if (!part.isStudents()) {
                continue;
            }
            Thread thread = new Thread(() -> found.put(part, probe(part)), "probe of " + part.className);
            thread.setDaemon(true);
            threads.put(part, thread);
            thread.start();
        }
        long deadline = System.nanoTime() + limitMillis * 1_000_000;
        try {
            for (Thread thread : threads.values()) {
                long left = deadline - System.nanoTime();
                if (left > 0) {
                    thread.join(Math.max(1, left / 1_000_000));
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        Set<Part> stubs = EnumSet.noneOf(Part.class);
        for (Part part : Part.values()) {
            Finding finding = found.get(part);
            if (finding != null && finding.stub) {
                stubs.add(part);
            }
        }
        return stubs;
    }

    /**
     * The line that says which tasks are still stubs and where to start, or null when none is:
     * "Still stubs: Task 1 (Camera rays), Task 2 (Sphere), …. Start with Task 1: the TODO(Task 1)
     * comments in src/main/java/ray/camera/PerspectiveCamera.java and OrthographicCamera.java (see
     * docs/assignment.md)." A task whose parts are only partly stubs is named by those parts
     * ("Task 1 (OrthographicCamera)"). The task to start with is the first stub in the table of
     * tasks' order, which gives pictures earliest (the cameras, the group, then the shapes), an
     * extra-credit task last. Plain ASCII, so that any console shows it.
     */
    public static String stillStubsLine(Set<Part> stubs) {
        if (stubs.isEmpty()) {
            return null;
        }
        Assignment assignment = Assignment.current();
        Map<Integer, List<Part>> byTask = new TreeMap<>();
        for (Part part : Part.values()) {
            if (stubs.contains(part) && part.isStudents()) {
                byTask.computeIfAbsent(part.task(), t -> new ArrayList<>()).add(part);
            }
        }
        if (byTask.isEmpty()) {
            return null;
        }
        List<String> named = new ArrayList<>();
        for (Map.Entry<Integer, List<Part>> entry : byTask.entrySet()) {
            Task task = assignment.task(entry.getKey()).orElseThrow();
            List<Part> parts = entry.getValue();
            String title = parts.size() == task.classNames().size() ? task.title() + (assignment.isExtraCredit(task.id()) ? ", extra credit" : "")
                    : String.join(" and ", parts.stream().map(p -> p.className).toArray(String[]::new));
            named.add("Task " + entry.getKey() + " (" + title + ")");
        }
        Task start = null;
        for (boolean extraCredit : new boolean[] {false, true}) {
            for (Task task : assignment.table().all()) {
                if (start == null && assignment.isExtraCredit(task.id()) == extraCredit && byTask.containsKey(assignment.number(task.id()))) {
                    start = task;
                }
            }
        }
        int number = assignment.number(start.id());
        List<Part> files = byTask.get(number);
        String where = "the TODO(Task " + number + ") " + (files.size() == 1 ? "comment" : "comments") + " in " + filesInWords(files)
                + " (see docs/assignment.md).";
        String next = assignment.isExtraCredit(start.id()) ? "For the extra credit: " + where : "Start with Task " + number + ": " + where;
        return (stubs.size() == 1 ? "Still a stub: " : "Still stubs: ") + String.join(", ", named) + ". " + next;
    }

    /** "src/main/java/ray/camera/PerspectiveCamera.java and OrthographicCamera.java": later files in the first one's folder by name alone. */
    private static String filesInWords(List<Part> parts) {
        String first = parts.get(0).file;
        String folder = first.substring(0, first.lastIndexOf('/') + 1);
        StringBuilder words = new StringBuilder(first);
        for (Part part : parts.subList(1, parts.size())) {
            words.append(" and ").append(part.file.startsWith(folder) ? part.file.substring(folder.length()) : part.file);
        }
        return words.toString();
    }

    // The probes. Each case is one the stub gets wrong and any finished solution gets right.

    /**
     * A camera at the origin looking along −z with a 2 × 2 image plane (1 unit away): the ray through
     * the center must look along −z from the origin, and the one through the upper-right corner up and
     * to the right, from {@code cornerOrigin} along {@code cornerDirection}. The stub's rays
     * (start = end) cannot reach anything.
     */
    private static Finding camera(Camera camera, Vec3 cornerOrigin, Vec3 cornerDirection) {
        String name = camera.getClass().getSimpleName() + ".generateRay";
        camera.setViewWidth(2);
        camera.setViewHeight(2);
        camera.complete();
        Ray center = camera.generateRay(0.5, 0.5);
        Ray corner = camera.generateRay(1, 1);
        Ray lowerLeft = camera.generateRay(0.25, 0.25);
        boolean stub = cannotReachAnything(center) && cannotReachAnything(corner) && cannotReachAnything(lowerLeft);
        String problem = emptyRayProblem(name, center);
        if (problem == null && (!close(center.origin, Vec3.ZERO) || !sameDirection(center.direction, new Vec3(0, 0, -1)))) {
            problem = name + "(0.5, 0.5) of a camera at the origin looking along −z returned origin " + center.origin
                    + ", direction " + center.direction + "; expected origin (0, 0, 0) and a direction along (0, 0, −1)";
        }
        if (problem == null) {
            problem = emptyRayProblem(name, corner);
        }
        if (problem == null) {
            if (!close(corner.origin, cornerOrigin) || !sameDirection(corner.direction, cornerDirection)) {
                problem = name + "(1, 1), the upper-right corner of a 2 × 2 image plane, returned origin " + corner.origin
                        + ", direction " + corner.direction + "; expected origin " + cornerOrigin + " and a direction along " + cornerDirection;
            }
        }
        return new Finding(stub, problem);
    }

    /** The stub's ray: one made, but with an empty segment or no direction, so that nothing can be hit. */
    private static boolean cannotReachAnything(Ray ray) {
        return ray != null && ray.origin != null && ray.direction != null && (!(ray.start < ray.end) || ray.direction.lengthSquared() == 0);
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

    /**
     * A scene of one surface hit at t = 3 by rays from (0, 0, 5) along −z, whose hits shade to
     * (0.2, 0.4, 0.6), under a sky of (0.1, 0.3, 0.5): the ray straight ahead must bring back the
     * shaded color, and one sent the other way the sky. The stub brings back black for both.
     */
    private static Finding rayTracer() {
        RayTracer tracer = new RayTracer();
        Vec3 shaded = new Vec3(0.2, 0.4, 0.6);
        Vec3 sky = new Vec3(0.1, 0.3, 0.5);
        tracer.use(new HitAt(3), sky, (hit, ray, depth) -> hit.t == 3 ? shaded : Vec3.ZERO);
        tracer.complete();
        Vec3 ahead = tracer.shadeRay(ahead(), 0);
        Vec3 away = tracer.shadeRay(new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, 1), 0, 1), 0);
        boolean stub = isBlack(ahead) && isBlack(away);
        String problem = ahead == null || !close(ahead, shaded)
                ? "RayTracer.shadeRay returned " + ahead + " for a ray that hits a surface whose hit shades to " + shaded + "; expected " + shaded
                : away == null || !close(away, sky) ? "RayTracer.shadeRay returned " + away + " for a ray that hits nothing; expected the background "
                        + sky : null;
        return new Finding(stub, problem);
    }

    /** A unit sphere at the origin: straight ahead (t = 4), from inside it, and along a long slanted direction. */
    private static Finding sphere() {
        Surface sphere = new Sphere(Vec3.ZERO, 1).complete();
        return surface("Sphere.intersect", "a unit sphere 5 units ahead of the ray", sphere, 4, ahead(),
                new Ray(Vec3.ZERO, new Vec3(1, 0, 0)), new Ray(new Vec3(3, 4, 5), new Vec3(-6, -8, -10)));
    }

    /** A triangle in the plane z = 0 around the origin: straight ahead (t = 5), from behind, and slanted. */
    private static Finding triangle() {
        Surface triangle = new Triangle(new Vec3(-1, -1, 0), new Vec3(1, -1, 0), new Vec3(0, 1, 0)).complete();
        return surface("Triangle.intersect", "a triangle 5 units straight ahead of the ray", triangle, 5, ahead(),
                new Ray(new Vec3(0, 0, -5), new Vec3(0, 0, 1)), new Ray(new Vec3(1, 1, 2), new Vec3(-1, -1.2, -2)));
    }

    /** The top cap straight below the ray (t = 2), the side from outside and from inside. */
    private static Finding cylinder() {
        Surface cylinder = new Cylinder(new Vec3(0, -3, 0), 1, 2).complete();
        return surface("Cylinder.intersect", "the top cap of a cylinder straight below the ray (direction (0, −2, 0))", cylinder, 2,
                new Ray(new Vec3(0, 3, 0), new Vec3(0, -2, 0)), new Ray(new Vec3(5, -2, 0), new Vec3(-1, 0, 0)),
                new Ray(new Vec3(0, -2, 0), new Vec3(1, 0, 0)));
    }

    /**
     * The box of a triangle and of a sphere, and the slab test of a ray through the cube from −1 to 1
     * and of one beside it: the stub returns no box and misses every box.
     */
    private static Finding boundingBoxes() {
        BoundingBoxes boxes = new BoundingBoxes();
        Vec3 a = new Vec3(0, 0, 0);
        Vec3 b = new Vec3(2, 0, 0);
        Vec3 c = new Vec3(0, 3, 1);
        Box triangle = boxes.ofTriangle(a, b, c);
        Box sphere = boxes.ofSphere(new Vec3(1, 2, 3), 2);
        Box cube = new Box(new Vec3(-1, -1, -1), new Vec3(1, 1, 1));
        boolean through = boxes.hit(cube, ahead());
        Ray besideRay = new Ray(new Vec3(3, 0, 5), new Vec3(0, 0, -1));
        boolean beside = boxes.hit(cube, besideRay);
        boolean stub = triangle == null && sphere == null && !through && !beside;
        Box triangleBox = new Box(new Vec3(0, 0, 0), new Vec3(2, 3, 1));
        Box sphereBox = new Box(new Vec3(-1, 0, 1), new Vec3(3, 4, 5));
        String problem = null;
        if (!triangleBox.equals(triangle)) {
            problem = "BoundingBoxes.ofTriangle(" + a + ", " + b + ", " + c + ") returned " + triangle + "; expected " + triangleBox;
        } else if (!sphereBox.equals(sphere)) {
            problem = "BoundingBoxes.ofSphere((1.0, 2.0, 3.0), 2.0) returned " + sphere + "; expected " + sphereBox;
        } else if (!through) {
            problem = "BoundingBoxes.hit misses " + cube + " for a ray from (0, 0, 5) along −z, straight through it";
        } else if (beside) {
            problem = "BoundingBoxes.hit reports a hit on " + cube + " for a ray from (3, 0, 5) along −z, which passes beside it";
        }
        return new Finding(stub, problem);
    }

    /**
     * Six plates one behind another, hit head on: the students' build over them must give a tree the
     * framework accepts, and their searches over a tree the framework made (two leaves) must find the
     * nearest plate and see that something blocks the ray. The stub builds nothing and finds nothing.
     */
    private static Finding bvhTree() {
        double[] depths = {-3, 1, -1, 2, 0, -2};
        Hittable[] plates = new Hittable[depths.length];
        Box[] boxes = new Box[depths.length];
        for (int i = 0; i < depths.length; i++) {
            plates[i] = new Plate(depths[i]);
            boxes[i] = new Box(new Vec3(-0.5, -0.5, depths[i]), new Vec3(0.5, 0.5, depths[i]));
        }
        Box all = boxes[0];
        for (Box box : boxes) {
            all = all.union(box);
        }
        BvhNode halves = BvhNode.inner(all, BvhNode.leaf(boxes[0].union(boxes[1]).union(boxes[2]), 0, 3),
                BvhNode.leaf(boxes[3].union(boxes[4]).union(boxes[5]), 3, 6));
        StudentBvh.Search search = StudentBvh.withRoot(plates, boxes, halves).search();
        IntersectionRecord out = new IntersectionRecord();
        boolean closest = search.closestHit(out, ahead(), null);
        boolean any = search.anyHit(ahead(), null);
        String built = null;
        boolean nothingBuilt = false;
        try {
            StudentBvh.build(plates, boxes);
        } catch (BrokenTree e) {
            built = e.getMessage();
            nothingBuilt = e.nothingBuilt;
        }
        boolean stub = !closest && !any && nothingBuilt;
        String problem = null;
        if (built != null) {
            problem = "over six plates one behind another, " + built;
        } else if (!closest) {
            problem = "BvhTree.closestHit finds nothing for a ray from (0, 0, 5) along −z through six plates (a tree the framework made of two leaves)";
        } else if (out.t != 3) {
            problem = "BvhTree.closestHit finds a plate at t = " + out.t + " for a ray from (0, 0, 5) along −z through six plates; the nearest is at t = 3";
        } else if (!any) {
            problem = "BvhTree.anyHit returns false for a ray from (0, 0, 5) along −z through six plates";
        }
        return new Finding(stub, problem);
    }

    /** A unit square facing the z axis at z = {@code depth}: what the tree probe searches. */
    private static final class Plate implements Hittable {
        private final double depth;

        Plate(double depth) {
            this.depth = depth;
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            if (ray.direction.z == 0) {
                return false;
            }
            double t = (depth - ray.origin.z) / ray.direction.z;
            Vec3 p = ray.pointAt(t);
            if (!(ray.start < t && t < ray.end) || Math.abs(p.x) > 0.5 || Math.abs(p.y) > 0.5) {
                return false;
            }
            out.t = t;
            out.location = p;
            out.normal = new Vec3(0, 0, 1);
            return true;
        }

        @Override
        public boolean intersectsAny(Ray ray) {
            return intersect(new IntersectionRecord(), ray);
        }

        @Override
        public Bounds bounds() {
            return new Bounds(-0.5, -0.5, depth, 0.5, 0.5, depth);
        }
    }

    /** From (0, 0, 5) along −z. */
    private static Ray ahead() {
        return new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1));
    }

    /**
     * A surface that every ray hits: the stub's misses them all. The plain case is the first ray,
     * which must hit at {@code expectedT}.
     */
    private static Finding surface(String method, String what, Surface surface, double expectedT, Ray plain, Ray... others) {
        IntersectionRecord out = new IntersectionRecord();
        boolean hit = surface.intersect(out, plain);
        boolean stub = !hit;
        for (Ray ray : others) {
            stub &= !surface.intersect(new IntersectionRecord(), ray);
        }
        String problem = null;
        if (!hit) {
            problem = method + " misses " + what + " (expected a hit at t = " + expectedT + ")";
        } else if (Math.abs(out.t - expectedT) > 1e-9 * expectedT) {
            problem = method + " hits " + what + " at t = " + out.t + "; expected t = " + expectedT;
        }
        return new Finding(stub, problem);
    }

    /** Two stand-ins hit at t = 7 and t = 3: the group must report the closer; the stub reports none, nor in a group of one. */
    private static Finding group() {
        Group group = new Group();
        group.addSurface(new HitAt(7));
        group.addSurface(new HitAt(3));
        IntersectionRecord out = new IntersectionRecord();
        boolean hit = group.intersect(out, ahead());
        Group one = new Group();
        one.addSurface(new HitAt(2));
        boolean stub = !hit && !one.intersect(new IntersectionRecord(), ahead());
        String problem = !hit ? "Group.intersect finds no hit in a group of two surfaces that are both hit"
                : out.t != 3 ? "Group.intersect reports t = " + out.t + " for two surfaces hit at t = 7 and t = 3; expected the closer, t = 3"
                : null;
        return new Finding(stub, problem);
    }

    /**
     * A 2 × 2 texture of four colors, none black: the lookup at each texel's center (u = column / 2
     * and v = 1 − row / 2, the row counted from the top) must give that texel. The stub gives black
     * everywhere.
     */
    private static Finding texture(java.util.function.Function<Image, Texture> make) {
        Image image = new Image(2, 2);
        for (int i = 0; i < 2; i++) {
            for (int j = 0; j < 2; j++) {
                image.set(i, j, new Vec3(i, j, 0.5)); // j counts from the bottom
            }
        }
        Texture texture = make.apply(image);
        boolean stub = true;
        String problem = null;
        for (int column = 0; column < 2; column++) {
            for (int row = 0; row < 2; row++) {
                double u = 0.5 * column;
                double v = 1 - 0.5 * row;
                Vec3 expected = image.get(column, 1 - row);
                Vec3 color = texture.getTexColor(u, v);
                stub &= isBlack(color);
                if (problem == null && (color == null || !close(color, expected))) {
                    problem = texture.getClass().getSimpleName() + ".getTexColor(" + u + ", " + v + ") on a 2 × 2 image returned "
                            + color + "; expected texel (" + column + ", " + row + ") counted from the top-left, " + expected;
                }
            }
        }
        return new Finding(stub, problem);
    }

    /**
     * A point at the origin facing +z, seen from straight above, under one light of intensity 4 at
     * distance 2 straight above it, with nothing in the way: the shader (kd = (0.5, 0.25, 1)) must
     * return {@code expected}. The stub returns black, here and with the light moved aside.
     */
    private static Finding lighting(Shader shader, Vec3 expected) {
        String name = shader.getClass().getSimpleName() + ".shade";
        if (shader instanceof DirectLighting) {
            ((DirectLighting) shader).setDiffuseColor(new Vec3(0.5, 0.25, 1));
        }
        shader.complete();
        IntersectionRecord hit = new IntersectionRecord();
        hit.t = 2;
        hit.location = Vec3.ZERO;
        hit.normal = new Vec3(0, 0, 1);
        Ray ray = new Ray(new Vec3(0, 0, 2), new Vec3(0, 0, -1));
        Vec3 above = shader.shade(hit, ray, unblocked(new Light(new Vec3(0, 0, 2), new Vec3(4, 4, 4))), 0);
        Vec3 aside = shader.shade(hit, ray, unblocked(new Light(new Vec3(1, 0, 1), new Vec3(2, 2, 2))), 0);
        boolean stub = isBlack(above) && isBlack(aside);
        String problem = above != null && close(above, expected) ? null
                : name + " returned " + above + " for a point facing a light of intensity (4, 4, 4) straight above it at distance 2 (kd = "
                        + "(0.5, 0.25, 1)" + (shader instanceof Phong ? ", ks = (1, 1, 1), p = 10, seen from straight above" : "")
                        + (shader instanceof ReflectionShader ? ", the Lambertian BRDF ρd/π, seen from straight above, no mirror term" : "")
                        + ", nothing in the way); expected " + expected;
        return new Finding(stub, problem);
    }

    /** ρd/π, the probes' own BRDF: the reflection shader's probe does not depend on the students' BRDFs. */
    private static final class ProbeBrdf extends LambertianBrdfFormula {
        @Override
        public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
            return rhoD.times(1 / Math.PI);
        }
    }

    /** A BRDF's value for ρd = (0.5, 0.25, 1) with light and eye along the normal, and with both slanted. */
    /** D and G1 along the normal (α = 0.5): D = 1/(πα²) = 4/π, G1 = 1; the stub's 0 for both. */
    private static Finding distribution(MicrofacetDistribution distribution) {
        Vec3 n = new Vec3(0, 0, 1);
        double d = distribution.normalDistribution(n, n);
        double g1 = distribution.masking(n, n, n);
        boolean stub = d == 0 && g1 == 0;
        String name = distribution.getClass().getSimpleName();
        String problem = !close(d, 4 / Math.PI) ? name + ".normalDistribution(n, n) with α = 0.5 returned " + d + "; expected 1/(πα²) = " + 4 / Math.PI
                : !close(g1, 1) ? name + ".masking(n, n, n) with α = 0.5 returned " + g1 + "; expected 1 (nothing is hidden along the normal)" : null;
        return new Finding(stub, problem);
    }

    /** F head on (nt = 1.5): R0 = 0.04; the stub's 0, also at grazing (where F is 1). */
    private static Finding fresnel() {
        Fresnel fresnel = new Fresnel(1.5);
        double head = fresnel.reflectance(1);
        double grazing = fresnel.reflectance(0);
        boolean stub = head == 0 && grazing == 0;
        String problem = close(head, 0.04) ? null : "Fresnel.reflectance(1) with nt = 1.5 returned " + head + "; expected R0 = ((nt − 1)/(nt + 1))² = 0.04";
        return new Finding(stub, problem);
    }

    private static boolean close(double value, double expected) {
        return Math.abs(value - expected) <= 1e-9 * Math.max(1, Math.abs(expected));
    }

    private static Finding brdf(Brdf brdf, Vec3 expected) {
        Vec3 rhoD = new Vec3(0.5, 0.25, 1);
        Vec3 n = new Vec3(0, 0, 1);
        Vec3 head = brdf.value(rhoD, n, n, n);
        Vec3 slanted = brdf.value(rhoD, n, new Vec3(0.6, 0, 0.8), new Vec3(0, 0.6, 0.8));
        boolean stub = isBlack(head) && isBlack(slanted);
        String problem = head != null && close(head, expected) ? null
                : brdf.getClass().getSimpleName() + ".value returned " + head + " for ρd = (0.5, 0.25, 1)"
                        + (brdf instanceof PhongBrdf ? ", ks = (1, 1, 1), p = 10" : "")
                        + (brdf instanceof MicrofacetBrdf ? ", k_mf = (1, 1, 1), GGX with α = 0.5, nt = 1.5" : "") + " with the light and the eye along the normal; expected "
                        + expected;
        return new Finding(stub, problem);
    }

    private static boolean isBlack(Vec3 color) {
        return color != null && color.x == 0 && color.y == 0 && color.z == 0;
    }

    /** One light, nothing in the way of it, no mirror rays. */
    private static ShadingContext unblocked(Light light) {
        return new ShadingContext() {
            @Override
            public List<Light> lights() {
                return List.of(light);
            }

            @Override
            public boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition) {
                return true;
            }

            @Override
            public Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth) {
                return Vec3.ZERO;
            }
        };
    }

    private static boolean close(Vec3 a, Vec3 b) {
        return a.minus(b).length() <= 1e-9;
    }

    private static boolean sameDirection(Vec3 d, Vec3 expected) {
        return d.isFinite() && d.lengthSquared() > 0 && d.normalized().minus(expected.normalized()).length() <= 1e-9;
    }

    /** A stand-in for the group's probe: every ray whose open segment holds {@code t} hits it there. */
    private static final class HitAt extends Surface {
        private final double t;

        HitAt(double t) {
            this.t = t;
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            if (!(ray.start < t && t < ray.end)) {
                return false;
            }
            out.t = t;
            out.location = ray.pointAt(t);
            out.normal = new Vec3(0, 0, 1);
            out.surface = this;
            return true;
        }

        @Override
        public String toString() {
            return "a surface hit at t = " + t;
        }
    }
}
