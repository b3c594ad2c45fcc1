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
import ray.surface.Sketch;
import ray.surface.Surface;
import ray.surface.TriangleSurface;

/**
 * The scene as the explore page draws it (top and side views): the camera, the lights, and every
 * surface in world coordinates, groups and placements resolved. Each surface sketches itself
 * ({@link Surface#sketch}): a sphere, box or cylinder that a placement only moves keeps its shape;
 * one it rotates or scales is drawn as its world bounding box ("other") or its triangles, which is
 * all a sketch needs. A mesh sends at most {@value #MAX_TRIANGLES} triangles.
 */
final class SceneOutline {
    static final int MAX_TRIANGLES = 4000;

    private final JsonArray surfaces = new JsonArray();
    private final SurfaceNames names = new SurfaceNames();
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
        surface.sketch(new Drawing(name), toWorld);
    }

    /** One surface's drawing, each shape it sketches an entry under its name. */
    private final class Drawing implements Sketch {
        private final String name;

        Drawing(String name) {
            this.name = name;
        }

        @Override
        public void sphere(Vec3 center, double radius) {
            JsonObject o = entry("sphere", name);
            o.add("center", vec(center));
            o.add("radius", num(radius));
            include(Bounds.around(center, radius));
        }

        @Override
        public void cylinder(Vec3 center, double radius, double height) {
            JsonObject o = entry("cylinder", name);
            o.add("center", vec(center));
            o.add("radius", num(radius));
            o.add("height", num(height));
            Vec3 half = new Vec3(radius, height / 2, radius);
            include(Bounds.of(center.minus(half), center.plus(half)));
        }

        @Override
        public void box(Vec3 min, Vec3 max) {
            shape("box", name, min, max);
        }

        @Override
        public void triangle(Vec3 a, Vec3 b, Vec3 c) {
            entry("triangle", name).add("vertices", vertices(a, b, c));
        }

        @Override
        public void mesh(List<? extends TriangleSurface> triangles, Affine toWorld) {
            JsonObject o = entry("mesh", name);
            JsonArray list = new JsonArray();
            for (int k = 0; k < triangles.size() && k < MAX_TRIANGLES; k++) {
                TriangleSurface t = triangles.get(k);
                list.add(vertices(toWorld.applyToPoint(t.getV0()), toWorld.applyToPoint(t.getV1()), toWorld.applyToPoint(t.getV2())));
            }
            o.add("triangles", list);
            o.addProperty("truncated", triangles.size() > MAX_TRIANGLES);
        }

        @Override
        public void parts(Surface whole, Affine toWorld) {
            List<Surface> children = whole.children();
            for (int k = 0; k < children.size(); k++) {
                add(children.get(k), toWorld, name + " › #" + (k + 1) + " " + names.of(children.get(k)));
            }
        }

        @Override
        public void bounds(Bounds b) {
            if (b.isFinite() && !b.isEmpty()) {
                shape("other", name, new Vec3(b.minX, b.minY, b.minZ), new Vec3(b.maxX, b.maxY, b.maxZ));
            }
        }
    }

    private JsonArray vertices(Vec3... world) {
        JsonArray vertices = new JsonArray();
        for (Vec3 p : world) {
            vertices.add(vec(p));
            include(p);
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
}
