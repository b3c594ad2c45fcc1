package ray.inspect;

import static ray.inspect.JsonNumbers.num;
import static ray.inspect.JsonNumbers.vec;

import com.google.gson.JsonArray;
import com.google.gson.JsonNull;
import com.google.gson.JsonObject;
import java.util.List;
import ray.camera.Camera;
import ray.camera.OrthographicCamera;
import ray.camera.PinholeCamera;
import ray.math.Affine;
import ray.math.Bounds;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Light;
import ray.surface.Box;
import ray.surface.CylinderShape;
import ray.surface.Mesh;
import ray.surface.SphereShape;
import ray.surface.Surface;
import ray.surface.TriangleShape;

/**
 * The scene as the explore page draws it (top and side views): the camera, the lights, and every
 * surface in world coordinates, groups and placements resolved. A sphere, box or cylinder that a
 * placement only moves keeps its shape; one it rotates or scales is drawn as its world bounding box
 * ("other"), which is all a sketch needs. A mesh sends at most {@value #MAX_TRIANGLES} triangles.
 */
final class SceneOutline {
    static final int MAX_TRIANGLES = 4000;

    private final JsonArray surfaces = new JsonArray();
    private final ray.inspect.SurfaceNames names = new ray.inspect.SurfaceNames();
    private Bounds bounds = Bounds.EMPTY;

    private SceneOutline() {
    }

    /** Adds "camera", "lights", "surfaces" and "bounds" to {@code into}. */
    static void of(Scene scene, JsonObject into) {
        SceneOutline outline = new SceneOutline();
        List<Surface> top = scene.getSurfaces().children();
        for (int k = 0; k < top.size(); k++) {
            outline.add(top.get(k), Affine.IDENTITY, "#" + (k + 1) + " " + outline.names.of(top.get(k)));
        }
        Camera camera = scene.getCamera();
        outline.include(camera.getViewPoint());
        JsonArray lights = new JsonArray();
        for (Light light : scene.getLights()) {
            JsonObject l = new JsonObject();
            l.add("position", vec(light.getPosition()));
            l.add("intensity", vec(light.getIntensity()));
            lights.add(l);
            outline.include(light.getPosition());
        }
        into.add("camera", camera(camera));
        into.add("lights", lights);
        into.add("surfaces", outline.surfaces);
        Bounds b = outline.bounds;
        JsonObject box = new JsonObject();
        box.add("min", vec(new Vec3(b.minX, b.minY, b.minZ)));
        box.add("max", vec(new Vec3(b.maxX, b.maxY, b.maxZ)));
        into.add("bounds", box);
    }

    private static JsonObject camera(Camera camera) {
        JsonObject c = new JsonObject();
        boolean perspective = camera instanceof PinholeCamera;
        c.addProperty("kind", perspective ? "perspective" : camera instanceof OrthographicCamera ? "orthographic" : "other");
        c.add("viewPoint", vec(camera.getViewPoint()));
        c.add("viewDir", vec(camera.getViewDir()));
        c.add("viewUp", vec(camera.getViewUp()));
        c.add("u", vec(camera.getU()));
        c.add("v", vec(camera.getV()));
        c.add("w", vec(camera.getW()));
        c.add("viewWidth", num(camera.getViewWidth()));
        c.add("viewHeight", num(camera.getViewHeight()));
        c.add("projDistance", perspective ? num(((PinholeCamera) camera).getProjDistance()) : JsonNull.INSTANCE);
        return c;
    }

    private void add(Surface surface, Affine toWorld, String name) {
        boolean moves = isTranslation(toWorld);
        if (surface instanceof Mesh || surface instanceof Box) {
            if (surface instanceof Box && moves) {
                Box box = (Box) surface;
                shape("box", name, toWorld.applyToPoint(box.getMinPt()), toWorld.applyToPoint(box.getMaxPt()));
                return;
            }
            triangles(surface, toWorld, name);
            return;
        }
        if (surface instanceof SphereShape && moves) {
            SphereShape s = (SphereShape) surface;
            JsonObject o = entry("sphere", name);
            Vec3 center = toWorld.applyToPoint(s.getCenter());
            o.add("center", vec(center));
            o.add("radius", num(s.getRadius()));
            include(Bounds.around(center, s.getRadius()));
            return;
        }
        if (surface instanceof CylinderShape && moves) {
            CylinderShape c = (CylinderShape) surface;
            JsonObject o = entry("cylinder", name);
            Vec3 center = toWorld.applyToPoint(c.getCenter());
            o.add("center", vec(center));
            o.add("radius", num(c.getRadius()));
            o.add("height", num(c.getHeight()));
            double r = c.getRadius();
            double h = c.getHeight() / 2;
            include(Bounds.of(center.minus(new Vec3(r, h, r)), center.plus(new Vec3(r, h, r))));
            return;
        }
        if (surface instanceof TriangleShape) {
            TriangleShape t = (TriangleShape) surface;
            JsonObject o = entry("triangle", name);
            o.add("vertices", triangle(t, toWorld));
            return;
        }
        List<Surface> children = surface.children();
        if (children.isEmpty()) {
            Bounds b = surface.bounds().transformed(toWorld);
            if (b.isFinite() && !b.isEmpty()) {
                shape("other", name, new Vec3(b.minX, b.minY, b.minZ), new Vec3(b.maxX, b.maxY, b.maxZ));
            }
            return;
        }
        Affine inner = toWorld.after(surface.childPlacement());
        for (int k = 0; k < children.size(); k++) {
            add(children.get(k), inner, name + " › #" + (k + 1) + " " + names.of(children.get(k)));
        }
    }

    private void triangles(Surface shape, Affine toWorld, String name) {
        JsonObject o = entry("mesh", name);
        JsonArray list = new JsonArray();
        List<Surface> parts = shape.children();
        Affine inner = toWorld.after(shape.childPlacement());
        for (int k = 0; k < parts.size() && k < MAX_TRIANGLES; k++) {
            if (parts.get(k) instanceof TriangleShape) {
                list.add(triangle((TriangleShape) parts.get(k), inner));
            }
        }
        o.add("triangles", list);
        o.addProperty("truncated", parts.size() > MAX_TRIANGLES);
    }

    private JsonArray triangle(TriangleShape t, Affine toWorld) {
        JsonArray vertices = new JsonArray();
        for (Vec3 p : new Vec3[] {t.getV0(), t.getV1(), t.getV2()}) {
            Vec3 world = toWorld.applyToPoint(p);
            vertices.add(vec(world));
            include(world);
        }
        return vertices;
    }

    private void shape(String kind, String name, Vec3 a, Vec3 b) {
        JsonObject o = entry(kind, name);
        Bounds box = Bounds.of(a, b);
        o.add("min", vec(new Vec3(box.minX, box.minY, box.minZ)));
        o.add("max", vec(new Vec3(box.maxX, box.maxY, box.maxZ)));
        include(box);
    }

    private JsonObject entry(String kind, String name) {
        JsonObject o = new JsonObject();
        o.addProperty("kind", kind);
        o.addProperty("name", name);
        surfaces.add(o);
        return o;
    }

    private void include(Vec3 p) {
        if (p != null && p.isFinite()) {
            include(Bounds.of(p));
        }
    }

    private void include(Bounds b) {
        if (b.isFinite()) {
            bounds = bounds.union(b);
        }
    }

    /** Whether the map only moves points (its linear part is the identity), so shapes keep their form. */
    private static boolean isTranslation(Affine m) {
        Vec3 x = m.applyToVector(new Vec3(1, 0, 0));
        Vec3 y = m.applyToVector(new Vec3(0, 1, 0));
        Vec3 z = m.applyToVector(new Vec3(0, 0, 1));
        return x.equals(new Vec3(1, 0, 0)) && y.equals(new Vec3(0, 1, 0)) && z.equals(new Vec3(0, 0, 1));
    }
}
