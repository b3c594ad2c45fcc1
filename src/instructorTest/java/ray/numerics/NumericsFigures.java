package ray.numerics;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import ray.IntersectionRecord;
import ray.Ray;
import ray.camera.Camera;
import ray.camera.PerspectiveCamera;
import ray.image.Image;
import ray.image.PngWriter;
import ray.math.Vec3;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneLoader;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.shading.ShadingContext;
import ray.surface.Mesh;
import ray.surface.Placements;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Transformed;
import ray.surface.Triangle;

/**
 * Renders the figures of docs/numerics.md: each hard case as the textbook formula renders it, next
 * to what the framework renders, same scene, same camera, one ray through each pixel centre. Writes
 * cracks.png, acne.png, contact-shadows.png and far-sphere.png, and prints the count of affected
 * pixels in every panel (the doc quotes them).
 *
 * <p>Only one thing changes between the panels of a figure: the triangle test (textbook variants
 * from {@link TextbookTriangles}), the sphere test ({@link TextbookSphere}), or where shadow rays
 * start ({@link Reintersection.Spawner}: no offset, a fixed t_min, or the framework's
 * {@code SecondaryRays}). The textbook surfaces report the solution's own primitive as the surface
 * hit, so shading and the framework's offsets work on their hits as on a student's.
 *
 * <p>Usage, from the project folder (it reads scenes/): {@code NumericsFigures [outputFolder [figure]]},
 * outputFolder by default docs/images/numerics, figure one of cracks, acne, contact, far (default all).
 * Under a minute (one thread), most of it the crack survey over every visible vertex. The images
 * are the same bytes on every run and machine (strict floating point, no randomness).
 */
public final class NumericsFigures {
    /** The background of inside-closed-mesh.xml: a camera ray that slips through the mesh shows it. */
    private static final int MAGENTA = 0xff00ff;
    /** The crack figure's microscope: a view this many ulps (of the vertex's largest coordinate) wide. */
    private static final double SPAN_ULPS = 100;
    /** Panels are this size unless the scene's own aspect asks otherwise. */
    private static final int WIDTH = 240;
    private static final int HEIGHT = 180;

    private NumericsFigures() {
    }

    public static void main(String[] args) throws IOException {
        System.setProperty("java.awt.headless", "true");
        Path folder = Path.of(args.length > 0 ? args[0] : "docs/images/numerics");
        String only = args.length > 1 ? args[1] : "";
        if (only.isEmpty() || only.equals("cracks")) {
            cracks(folder);
        }
        if (only.isEmpty() || only.equals("acne")) {
            acne(folder);
        }
        if (only.isEmpty() || only.equals("contact")) {
            contactShadows(folder);
        }
        if (only.isEmpty() || only.equals("far")) {
            farSphere(folder);
        }
    }

    // ---------------------------------------------------------------- figure 1: cracks

    /**
     * scenes/hard/inside-closed-mesh.xml with Möller–Trumbore, Cramer's rule and the watertight test.
     * A crack is only an ulp or two wide, so at the scene's own size no pixel centre falls in one;
     * the figure looks at a shared vertex through a camera whose view there is {@link #SPAN_ULPS}
     * ulps wide (same eye, narrower view), and the survey does the same at every visible vertex.
     */
    static void cracks(Path folder) throws IOException {
        Scene scene = SceneLoader.load(Path.of("scenes", "hard", "inside-closed-mesh.xml"));
        Surface robust = scene.getSurfaces();
        List<Surface> roots = List.of(TextbookSurfaces.withTriangles(robust, TextbookTriangles.MOLLER_TRUMBORE),
                TextbookSurfaces.withTriangles(robust, TextbookTriangles.CRAMER), robust);
        String[] names = {"Möller–Trumbore", "Cramer's rule", "watertight"};
        Camera camera = scene.getCamera();
        int size = scene.getWidth();

        BufferedImage whole = picture(scene, robust, camera, size, size, Reintersection.FRAMEWORK);
        System.out.printf(Locale.ROOT, "Figure 1 (cracks), whole view %dx%d: watertight %d magenta px", size, size, count(whole));
        for (int m = 0; m < 2; m++) {
            BufferedImage textbook = picture(scene, roots.get(m), camera, size, size, Reintersection.FRAMEWORK);
            System.out.printf(Locale.ROOT, ", %s %d magenta px (%d px differ from watertight)", names[m], count(textbook),
                    FigureSheet.differing(whole, textbook, 2));
        }
        System.out.println();

        // The mesh's vertices that the camera sees: a ray aimed at one meets the mesh there, not the box.
        Transformed room = (Transformed) robust.children().get(0);
        double[] xyz = ((Mesh) room.children().get(0)).getData().positions;
        Vec3 eye = camera.getViewPoint();
        Vec3 axis = camera.generateRay(0.5, 0.5).direction;
        Vec3 keyLight = scene.getLights().get(0).getPosition();
        List<Vec3> visible = new ArrayList<>();
        Vec3 central = null;
        for (int k = 0; k < xyz.length / 3; k++) {
            Vec3 vertex = room.toWorld().applyToPoint(new Vec3(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]));
            IntersectionRecord hit = new IntersectionRecord();
            if (robust.intersect(hit, new Ray(eye, vertex.minus(eye))) && Math.abs(hit.t - 1) < 1e-9) {
                visible.add(vertex);
                // The figure's vertex is lit by the key light, so that its faces differ in shade.
                boolean lit = !robust.intersect(new IntersectionRecord(), new Ray(vertex, keyLight.minus(vertex), 1e-6, 1 - 1e-9));
                if (lit && (central == null || angle(vertex.minus(eye), axis) < angle(central.minus(eye), axis))) {
                    central = vertex;
                }
            }
        }

        double span = SPAN_ULPS * Math.ulp(central.maxAbs());
        Camera microscope = microscope(eye, central, span, WIDTH, HEIGHT);
        double zoom = viewWidthAt(camera, central) / span;
        String zoomText = String.format(Locale.ROOT, "%.1e", zoom).replace("e+", "e");
        FigureSheet sheet = new FigureSheet(2);
        BufferedImage overview = picture(scene, robust, camera, HEIGHT, HEIGHT, Reintersection.FRAMEWORK);
        circle(overview, camera, central);
        sheet.add(overview, "the scene; circled: the vertex below");
        System.out.printf(Locale.ROOT, "  the lit vertex nearest the view's centre, %s, seen %.3g wide (%.0f ulps of %.3g, zoom x%.2g), %dx%d px:",
                central, span, SPAN_ULPS, central.maxAbs(), zoom, WIDTH, HEIGHT);
        for (int m = 0; m < 3; m++) {
            BufferedImage panel = picture(scene, roots.get(m), microscope, WIDTH, HEIGHT, Reintersection.FRAMEWORK);
            int n = count(panel);
            sheet.add(panel, String.format(Locale.ROOT, "%s, x%s: %d px", m == 2 ? "watertight" : names[m], zoomText, n));
            System.out.printf(Locale.ROOT, " %s %d (%.2f%%)", names[m], n, 100.0 * n / (WIDTH * HEIGHT));
        }
        System.out.println();
        PngWriter.write(sheet.draw(), folder.resolve("cracks.png"));

        // The same microscope at every visible vertex, with a quarter of the pixels.
        int w = WIDTH / 2;
        int h = HEIGHT / 2;
        long[] total = new long[3];
        int[] cracked = new int[3];
        int[] worst = new int[3];
        for (Vec3 vertex : visible) {
            Camera small = microscope(eye, vertex, SPAN_ULPS * Math.ulp(vertex.maxAbs()), w, h);
            for (int m = 0; m < 3; m++) {
                int n = count(picture(scene, roots.get(m), small, w, h, Reintersection.FRAMEWORK));
                total[m] += n;
                cracked[m] += n > 0 ? 1 : 0;
                worst[m] = Math.max(worst[m], n);
            }
        }
        System.out.printf(Locale.ROOT, "  every one of the %d visible vertices, %dx%d px each (%d px in all):", visible.size(), w, h,
                (long) visible.size() * w * h);
        for (int m = 0; m < 3; m++) {
            System.out.printf(Locale.ROOT, " %s %d magenta px (%.3f%%), %d vertices with some, at most %d at one;", names[m], total[m],
                    100.0 * total[m] / ((long) visible.size() * w * h), cracked[m], worst[m]);
        }
        System.out.println();
    }

    private static int count(BufferedImage picture) {
        return FigureSheet.count(picture, MAGENTA);
    }

    private static double angle(Vec3 a, Vec3 b) {
        return Math.acos(Math.max(-1, Math.min(1, a.normalized().dot(b.normalized()))));
    }

    /** A camera at {@code eye} looking at {@code target}, its view {@code span} wide at the target's distance. */
    static Camera microscope(Vec3 eye, Vec3 target, double span, int width, int height) {
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewPoint(eye);
        camera.setViewDir(target.minus(eye));
        double distance = target.minus(eye).length();
        camera.setProjDistance(1);
        camera.setViewWidth(span / distance);
        camera.setViewHeight(span / distance * height / width);
        camera.complete();
        return camera;
    }

    /** How wide the camera's view is at the depth of {@code target} along its view axis. */
    private static double viewWidthAt(Camera camera, Vec3 target) {
        Vec3 centre = camera.generateRay(0.5, 0.5).direction;
        Vec3 across = camera.generateRay(1, 0.5).direction.minus(camera.generateRay(0, 0.5).direction);
        double depth = target.minus(camera.getViewPoint()).dot(centre) / centre.length();
        return across.length() / centre.length() * depth;
    }

    /** Draws a circle around where {@code target} appears in the camera's picture. */
    private static void circle(BufferedImage picture, Camera camera, Vec3 target) {
        // The camera's image plane from its own rays: d0 to the centre, du and dv half the width and height.
        Vec3 d0 = camera.generateRay(0.5, 0.5).direction;
        Vec3 du = camera.generateRay(1, 0.5).direction.minus(d0);
        Vec3 dv = camera.generateRay(0.5, 1).direction.minus(d0);
        Vec3 d = target.minus(camera.getViewPoint());
        Vec3 p = d.times(d0.lengthSquared() / d.dot(d0)).minus(d0);
        double x = (0.5 + 0.5 * p.dot(du) / du.lengthSquared()) * picture.getWidth();
        double y = (0.5 - 0.5 * p.dot(dv) / dv.lengthSquared()) * picture.getHeight();
        Graphics2D g = picture.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(new Color(0, 90, 255));
        g.setStroke(new BasicStroke(2));
        g.drawOval((int) Math.round(x) - 8, (int) Math.round(y) - 8, 16, 16);
        g.dispose();
    }

    // ---------------------------------------------------------------- figure 2: shadow acne

    /**
     * A sphere on a ground of two triangles, at the origin and moved by (1e12, 1e12, 1e12), with
     * shadow rays from the hit point with t_min = 0, from it with a fixed t_min of 1e-6, and from
     * the framework's offset, in the scene's own coordinates; and the framework's offset from the
     * camera's frame, as the renderer works. Intersection is the solution's in every panel.
     * Counted: pixels more than 2 levels off the framework's render at the origin.
     */
    static void acne(Path folder) throws IOException {
        Scene atOrigin = sphereOnPlane(Vec3.ZERO);
        BufferedImage reference = render(atOrigin, Reintersection.FRAMEWORK);
        // The figures' pixel loop is the renderer's at one sample per pixel, to the bit.
        BufferedImage renderer = PngWriter.toBufferedImage(new Renderer(atOrigin, 1, 1).render().image, atOrigin.getExposure());
        if (FigureSheet.differing(reference, renderer, 0) != 0) {
            throw new IllegalStateException("the figures' pixel loop no longer matches the renderer");
        }
        List<Reintersection.Spawner> spawners = List.of(Reintersection.NO_OFFSET, Reintersection.fixedStart(1e-6), Reintersection.FRAMEWORK);
        String[] names = {"t_min 0", "fixed t_min 1e-6", "framework offset", "camera's frame"};
        FigureSheet sheet = new FigureSheet(4);
        for (double translate : new double[] {0, 1e10, 1e11, 1e12}) {
            Scene scene = sphereOnPlane(new Vec3(translate, translate, translate));
            String where = translate == 0 ? "origin" : String.format(Locale.ROOT, "%.0e", translate).replace("e+", "e");
            System.out.printf("Figure 2 (acne), at %s, px off the framework's render at the origin:", where);
            for (int s = 0; s < names.length; s++) {
                boolean cameraFrame = s == spawners.size();
                BufferedImage picture = cameraFrame ? render(scene.inCameraFrame(), Reintersection.FRAMEWORK) : render(scene, spawners.get(s));
                int off = FigureSheet.differing(reference, picture, 2);
                System.out.printf(Locale.ROOT, " %s %d (%.1f%%);", names[s], off, 100.0 * off / (WIDTH * HEIGHT));
                if (translate == 0 || translate == 1e12) {
                    String caption = s == 2 && translate == 0
                            ? where + ", " + names[s] + " (reference)" : String.format(Locale.ROOT, "%s, %s: %,d px off", where, names[s], off);
                    sheet.add(picture, caption);
                }
            }
            // Not in the figure: the framework's rule with 4 ulps instead of OFFSET_ULPS (what the solution's
            // own intersection code needs), to tell the offset's size from the rounding of the moved scene.
            System.out.printf(Locale.ROOT, " (the same rule with 4 ulps: %d)%n",
                    FigureSheet.differing(reference, render(scene, Reintersection.geometryOffset(4)), 2));
        }
        PngWriter.write(sheet.draw(), folder.resolve("acne.png"));
    }

    private static BufferedImage render(Scene scene, Reintersection.Spawner spawner) {
        return picture(scene, scene.getSurfaces(), scene.getCamera(), scene.getWidth(), scene.getHeight(), spawner);
    }

    /** A unit sphere resting on a ground of two triangles, one light, every position moved by {@code t}. */
    static Scene sphereOnPlane(Vec3 t) {
        Scene scene = new Scene();
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewPoint(t.plus(new Vec3(1.2, 2.4, 6)));
        camera.setViewDir(new Vec3(-1.2, -1.8, -6));
        camera.setProjDistance(1.2);
        camera.setViewWidth(1);
        camera.setViewHeight(0.75);
        camera.complete();
        scene.setCamera(camera);
        scene.setImage(WIDTH, HEIGHT);
        scene.setBackColor(new Vec3(0.45, 0.6, 0.85));
        scene.addLight(new Light(t.plus(new Vec3(-4, 7, 4)), new Vec3(90, 88, 84)));
        Sphere sphere = new Sphere(t.plus(new Vec3(0, 1, 0)), 1);
        sphere.setShader(new Lambertian(new Vec3(0.8, 0.3, 0.15)));
        scene.addSurface(sphere.complete());
        Vec3 a = t.plus(new Vec3(-8, 0, -8));
        Vec3 b = t.plus(new Vec3(-8, 0, 8));
        Vec3 c = t.plus(new Vec3(8, 0, 8));
        Vec3 d = t.plus(new Vec3(8, 0, -8));
        Lambertian ground = new Lambertian(new Vec3(0.7, 0.7, 0.68));
        for (Triangle triangle : List.of(new Triangle(a, b, c), new Triangle(a, c, d))) {
            triangle.setShader(ground);
            scene.addSurface(triangle.complete());
        }
        scene.complete();
        return scene;
    }

    // ---------------------------------------------------------------- figure 3: lost contact shadows

    /**
     * scenes/mesh-smooth.xml at its own size and scaled by 1e-3 as a whole ({@link MovedScenes}),
     * shadow rays from a fixed t_min of 1e-3 and from the framework's offset. Counted: pixels more
     * than 2 levels off the same method's render at scale 1. A second row enlarges the region under
     * the torus's front ×3.
     */
    static void contactShadows(Path folder) throws IOException {
        List<Reintersection.Spawner> spawners = List.of(Reintersection.fixedStart(1e-3), Reintersection.FRAMEWORK);
        int size = 240;
        BufferedImage[] full = new BufferedImage[3];
        String[] captions = new String[3];
        int k = 0;
        for (int s = 0; s < 2; s++) {
            BufferedImage original = picture(MovedScenes.load("mesh-smooth", 1, Vec3.ZERO, 1), spawners.get(s), size);
            BufferedImage scaled = picture(MovedScenes.load("mesh-smooth", 1e-3, Vec3.ZERO, 1), spawners.get(s), size);
            int off = FigureSheet.differing(original, scaled, 2);
            System.out.printf(Locale.ROOT, "Figure 3 (contact shadows), %s: scaled by 1e-3, %d px (%.2f%%) off its render at scale 1%n",
                    spawners.get(s), off, 100.0 * off / (size * size));
            if (s == 0) {
                full[k] = original;
                captions[k++] = "t_min 1e-3, scene at scale 1";
                full[k] = scaled;
                captions[k++] = String.format(Locale.ROOT, "t_min 1e-3, scaled 1e-3: %,d px off", off);
            } else {
                full[k] = scaled;
                captions[k++] = String.format(Locale.ROOT, "framework, scaled 1e-3: %d px off", off);
            }
        }
        // The contact under the front of the torus: an 80×80 region, each pixel 3×3.
        FigureSheet sheet = new FigureSheet(3);
        for (int i = 0; i < 3; i++) {
            sheet.add(boxed(full[i], CONTACT_X, CONTACT_Y, 80, 80), captions[i]);
        }
        for (int i = 0; i < 3; i++) {
            sheet.add(FigureSheet.enlarge(FigureSheet.crop(full[i], CONTACT_X, CONTACT_Y, 80, 80), 3), "the boxed region, x3");
        }
        PngWriter.write(sheet.draw(), folder.resolve("contact-shadows.png"));
    }

    private static final int CONTACT_X = 80;
    private static final int CONTACT_Y = 150;

    private static BufferedImage picture(Scene scene, Reintersection.Spawner spawner, int size) {
        return picture(scene, scene.getSurfaces(), scene.getCamera(), size, size, spawner);
    }

    /** A copy of the picture with a frame just outside the w×h region at (x, y), the region that is enlarged. */
    private static BufferedImage boxed(BufferedImage picture, int x, int y, int w, int h) {
        BufferedImage marked = FigureSheet.crop(picture, 0, 0, picture.getWidth(), picture.getHeight());
        Graphics2D g = marked.createGraphics();
        g.setColor(new Color(0, 90, 255));
        g.drawRect(x - 1, y - 1, w + 1, h + 1);
        g.dispose();
        return marked;
    }

    // ---------------------------------------------------------------- figure 4: far sphere

    /**
     * A unit sphere seen from 1e6, 1e7 and 1e8 away through a view 3 units wide at the sphere,
     * intersected by the textbook formula and by the solution. Counted: pixels whose camera ray the
     * sphere reports hit or missed against the exact answer for the same ray ({@link ExactSphere}).
     */
    static void farSphere(Path folder) throws IOException {
        FigureSheet sheet = new FigureSheet(2);
        for (double distance : new double[] {1e6, 1e7, 1e8}) {
            Scene scene = farSphereScene(distance);
            Surface robust = scene.getSurfaces();
            Surface textbook = TextbookSurfaces.withTextbookSpheres(robust);
            BufferedImage robustPicture = render(scene, Reintersection.FRAMEWORK);
            BufferedImage textbookPicture = picture(scene, textbook, scene.getCamera(), WIDTH, HEIGHT, Reintersection.FRAMEWORK);
            int textbookWrong = wrongHits(scene, textbook);
            int robustWrong = wrongHits(scene, robust);
            int off = FigureSheet.differing(robustPicture, textbookPicture, 2);
            String d = String.format(Locale.ROOT, "%.0e", distance).replace("e+0", "e").replace("e+", "e");
            System.out.printf(Locale.ROOT, "Figure 4 (far sphere), distance %s: hit/miss wrong on %d px (%.2f%%) with b^2-4ac, %d with the"
                    + " solution; %d px of the textbook render differ from the solution's%n", d, textbookWrong,
                    100.0 * textbookWrong / (WIDTH * HEIGHT), robustWrong, off);
            if (distance == 1e6) {
                continue;
            }
            boolean enlarged = distance == 1e7;
            sheet.add(enlarged ? boxed(textbookPicture, EDGE_X, EDGE_Y, 60, 45) : textbookPicture,
                    String.format(Locale.ROOT, "b² − 4ac, at %s: %,d px wrong", d, textbookWrong));
            sheet.add(enlarged ? boxed(robustPicture, EDGE_X, EDGE_Y, 60, 45) : robustPicture,
                    String.format(Locale.ROOT, "solution, at %s: %d px wrong", d, robustWrong));
            if (enlarged) {
                sheet.add(FigureSheet.enlarge(FigureSheet.crop(textbookPicture, EDGE_X, EDGE_Y, 60, 45), 4), "b² − 4ac, left edge x4");
                sheet.add(FigureSheet.enlarge(FigureSheet.crop(robustPicture, EDGE_X, EDGE_Y, 60, 45), 4), "solution, left edge x4");
            }
        }
        PngWriter.write(sheet.draw(), folder.resolve("far-sphere.png"));
    }

    private static final int EDGE_X = 18;
    private static final int EDGE_Y = 66;

    /** Pixels whose camera ray {@code root} reports hit or missed, unlike the exact answer for the unit sphere at the origin. */
    private static int wrongHits(Scene scene, Surface root) {
        int wrong = 0;
        for (int j = 0; j < scene.getHeight(); j++) {
            for (int i = 0; i < scene.getWidth(); i++) {
                Ray ray = scene.getCamera().generateRay((i + 0.5) / scene.getWidth(), (j + 0.5) / scene.getHeight());
                if (root.intersect(new IntersectionRecord(), ray) != ExactSphere.hits(ray, Vec3.ZERO, 1)) {
                    wrong++;
                }
            }
        }
        return wrong;
    }

    /** A unit sphere at the origin seen from {@code distance} away, the view 3 units wide at the sphere. */
    static Scene farSphereScene(double distance) {
        Vec3 direction = new Vec3(0.3, 0.25, 0.92).normalized();
        Scene scene = new Scene();
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewPoint(direction.times(distance));
        camera.setViewDir(direction.negate());
        camera.setProjDistance(1);
        camera.setViewWidth(3 / distance);
        camera.setViewHeight(3 / distance * HEIGHT / WIDTH);
        camera.complete();
        scene.setCamera(camera);
        scene.setImage(WIDTH, HEIGHT);
        scene.setBackColor(new Vec3(0.06, 0.07, 0.1));
        scene.addLight(new Light(new Vec3(-4, 8, 6), new Vec3(110, 105, 100)));
        Sphere sphere = new Sphere(Vec3.ZERO, 1);
        sphere.setShader(new Lambertian(new Vec3(0.15, 0.3, 0.8)));
        scene.addSurface(sphere.complete());
        scene.complete();
        return scene;
    }

    // ---------------------------------------------------------------- rendering

    /**
     * The scene's lights and background with {@code root} as its surfaces, seen by {@code camera}
     * at width×height, one ray through each pixel centre (as the renderer with one sample), new
     * rays leaving hits as {@code spawner} makes them.
     */
    static BufferedImage picture(Scene scene, Surface root, Camera camera, int width, int height, Reintersection.Spawner spawner) {
        Placements placements = Placements.of(root);
        ShadingContext shading = new ShadingContext() {
            @Override
            public List<Light> lights() {
                return scene.getLights();
            }

            @Override
            public boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition) {
                return !root.intersect(new IntersectionRecord(), spawner.toLight(hit, placements.geometryOf(hit), lightPosition));
            }

            @Override
            public Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth) {
                return trace(scene, root, spawner.leaving(hit, placements.geometryOf(hit), direction), depth, this);
            }
        };
        Image image = new Image(width, height);
        for (int j = 0; j < height; j++) {
            for (int i = 0; i < width; i++) {
                image.set(i, j, trace(scene, root, camera.generateRay((i + 0.5) / width, (j + 0.5) / height), 0, shading));
            }
        }
        return PngWriter.toBufferedImage(image, scene.getExposure());
    }

    private static Vec3 trace(Scene scene, Surface root, Ray ray, int depth, ShadingContext shading) {
        IntersectionRecord hit = new IntersectionRecord();
        return root.intersect(hit, ray) ? hit.surface.getShader().shade(hit, ray, shading, depth) : scene.getBackColor();
    }
}
