package ray.inspect;

import static ray.inspect.JsonNumbers.num;
import static ray.inspect.JsonNumbers.rgb;
import static ray.inspect.JsonNumbers.vec;

import com.google.gson.JsonArray;
import com.google.gson.JsonNull;
import com.google.gson.JsonObject;
import com.google.gson.JsonPrimitive;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.camera.Camera;
import ray.scene.Scene;
import ray.shading.Effect;
import ray.shading.Light;
import ray.shading.Shader;

/**
 * The facts {@code ray1 trace} prints for one pixel, as a JSON object for {@code ray1 explore}'s
 * page: the camera ray, what each surface says about it (a mesh or box as one entry whose
 * triangles are its children), the closest hit the scene's group picks, each light's shadow ray and
 * blocker and its shading terms, the radiance and the 8-bit value, and the trace's full text. The
 * numbers come from the same code as the printed trace ({@link ProbeTree}, {@link ShadowCheck},
 * {@link LightFacts}, {@link PixelValue}), so page and terminal never disagree. Student code that
 * throws becomes an {@code error} string where it threw, and the story goes on where it can.
 */
public final class PixelStory {
    private final Scene scene;
    private final String sceneLabel;
    private final SurfaceNames names = new SurfaceNames();

    public PixelStory(Scene scene, String sceneLabel) {
        this.scene = scene;
        this.sceneLabel = sceneLabel;
    }

    /**
     * The story of pixel (x, y), x from the left and y from the top (check it with
     * {@link PixelTrace#outOfRange} first). {@code value} is the pixel of the shown render when there
     * is one (so the page's number is the PNG's), else null to take the renderer's value for this
     * pixel alone; {@code reference} is the reference image's pixel there, or null.
     */
    public JsonObject of(int x, int y, int[] value, int[] reference) {
        PixelCoordinates pixel = new PixelCoordinates(scene, x, y);
        int i = pixel.i;
        int j = pixel.j;
        double u = pixel.u;
        double v = pixel.v;
        JsonObject story = new JsonObject();
        story.addProperty("x", x);
        story.addProperty("y", y);
        story.addProperty("i", i);
        story.addProperty("j", j);
        story.add("u", num(u));
        story.add("v", num(v));
        pixelValue(story, i, j, value);
        story.add("reference", reference == null ? JsonNull.INSTANCE : rgb(reference));
        Ray ray = cameraRay(story, u, v);
        story.add("hits", new JsonArray());
        story.add("closest", JsonNull.INSTANCE);
        story.add("closestError", JsonNull.INSTANCE);
        story.add("background", JsonNull.INSTANCE);
        story.add("lights", new JsonArray());
        story.add("shading", JsonNull.INSTANCE);
        if (ray != null) {
            List<ProbeNode> roots = ProbeTree.of(scene.getSurfaces(), ray);
            ProbeNode nearest = ProbeTree.nearest(ProbeTree.primitives(roots));
            JsonArray hits = new JsonArray();
            for (ProbeNode node : roots) {
                hits.add(node(node, ProbeTree.step(null, node, names), nearest));
            }
            story.add("hits", hits);
            closest(story, ray, roots, nearest);
        }
        StringWriter text = new StringWriter();
        try (PrintWriter out = new PrintWriter(text)) {
            new PixelTrace(scene, sceneLabel, false, 0).run(x, y, out);
        }
        story.addProperty("trace", text.toString());
        return story;
    }

    private void pixelValue(JsonObject story, int i, int j, int[] shown) {
        try {
            PixelValue value = PixelValue.render(scene, i, j, 0);
            story.add("value", rgb(shown != null ? shown : value.rgb8));
            story.add("radiance", vec(value.radiance));
            story.addProperty("samples", value.samples);
            story.add("valueError", JsonNull.INSTANCE);
        } catch (RuntimeException | StackOverflowError e) {
            story.add("value", shown != null ? rgb(shown) : JsonNull.INSTANCE);
            story.add("radiance", JsonNull.INSTANCE);
            story.add("samples", JsonNull.INSTANCE);
            story.addProperty("valueError", "the renderer threw " + Failure.oneLine(e));
        }
    }

    /** Adds "cameraRay" and returns the ray, or null when there is none to follow. */
    private Ray cameraRay(JsonObject story, double u, double v) {
        Camera camera = scene.getCamera();
        JsonObject c = new JsonObject();
        c.addProperty("call", camera.getClass().getSimpleName() + ".generateRay(" + Fmt.num(u) + ", " + Fmt.num(v) + ")");
        story.add("cameraRay", c);
        Ray ray;
        try {
            ray = camera.generateRay(u, v);
        } catch (RuntimeException | StackOverflowError e) {
            c.addProperty("error", "threw " + Failure.oneLine(e));
            return null;
        }
        c.add("error", JsonNull.INSTANCE);
        String problem = CameraRayCheck.problem(camera, ray);
        c.add("problem", problem == null ? JsonNull.INSTANCE : new JsonPrimitive(problem));
        if (ray == null || ray.origin == null || ray.direction == null) {
            return null;
        }
        c.add("origin", vec(ray.origin));
        c.add("direction", vec(ray.direction));
        c.add("start", num(ray.start));
        c.add("end", num(ray.end));
        c.addProperty("endText", Fmt.num(ray.end));
        return ray;
    }

    /** One surface as the page lists it: a primitive with its result, or a composite with its children and a one-line summary. */
    private JsonObject node(ProbeNode node, String path, ProbeNode nearest) {
        JsonObject n = new JsonObject();
        n.addProperty("path", path);
        n.addProperty("kind", kind(node));
        n.addProperty("transformed", node.transformed);
        if (node.isPrimitive()) {
            PrimitiveProbe test = node.test;
            n.addProperty("hit", test.hit && test.failure == null);
            n.add("error", test.failure == null ? JsonNull.INSTANCE : new JsonPrimitive("threw " + test.failure));
            if (test.hit) {
                n.add("t", num(test.record.t));
                n.add("location", vec(node.worldLocation()));
                n.add("normal", vec(node.worldNormal()));
            }
            JsonArray problems = new JsonArray();
            test.problems.forEach(problems::add);
            n.add("problems", problems);
            n.addProperty("nearest", node == nearest);
            return n;
        }
        JsonArray children = new JsonArray();
        for (ProbeNode child : node.children) {
            children.add(node(child, path + " › " + ProbeTree.step(node.surface, child, names), nearest));
        }
        n.add("children", children);
        n.addProperty("hit", node.primitives().stream().anyMatch(ProbeNode::isHit));
        n.addProperty("nearest", node.primitives().contains(nearest));
        n.addProperty("summary", summary(node, nearest));
        return n;
    }

    private static String summary(ProbeNode node, ProbeNode nearest) {
        if (node.children.stream().allMatch(ProbeNode::isPrimitive)) {
            return ProbePrinter.summary(node, nearest);
        }
        List<ProbeNode> primitives = node.primitives();
        long hits = primitives.stream().filter(ProbeNode::isHit).count();
        return Fmt.count(node.children.size(), "surface") + ", " + Fmt.count(primitives.size(), "primitive")
                + ": " + hits + " hit" + (primitives.contains(nearest) ? "  ← nearest inside" : "");
    }

    private static String kind(ProbeNode node) {
        String simple = node.surface.getClass().getSimpleName();
        return simple.isEmpty() ? "surface" : Character.toLowerCase(simple.charAt(0)) + simple.substring(1);
    }

    /** Adds the closest hit the group reports, its shading and each light's part. */
    private void closest(JsonObject story, Ray ray, List<ProbeNode> roots, ProbeNode nearest) {
        IntersectionRecord hit = new IntersectionRecord();
        boolean found;
        try {
            found = scene.getSurfaces().intersect(hit, ray.copy());
        } catch (RuntimeException | StackOverflowError e) {
            story.addProperty("closestError", "Group.intersect threw " + Failure.oneLine(e));
            return;
        }
        if (!found) {
            story.add("background", vec(scene.getBackColor()));
            if (nearest != null) {
                story.addProperty("closestError", "the scene's group reports no hit, but "
                        + ClosestHitReport.hitAlone(roots, nearest, names));
            }
            return;
        }
        JsonObject c = new JsonObject();
        c.addProperty("path", ClosestHitReport.surfacePath(hit, roots, names));
        c.add("t", num(hit.t));
        c.add("location", vec(hit.location));
        c.add("normal", vec(hit.normal));
        Shader shader = hit.surface == null ? null : hit.surface.getShader();
        c.addProperty("shader", hit.surface == null ? "none (the record names no surface)" : ShadingReport.describe(shader));
        c.addProperty("check", ClosestHitReport.check(hit, roots, nearest, names));
        // What the record claims that the contract rules out, as `ray1 trace` flags it.
        JsonArray flags = new JsonArray();
        for (String flag : RecordChecks.of(hit, ray)) {
            flags.add(flag);
        }
        c.add("recordChecks", flags);
        story.add("closest", c);
        String lacks = ClosestHitReport.lacks(hit);
        if (lacks != null) {
            story.addProperty("closestError", "the hit cannot be shaded: its record lacks " + lacks);
            return;
        }
        try {
            RecordedShading recorded = new RecordedShading(scene);
            // A shader that sums over the lights has a share of each to show.
            if (shader.effects().contains(Effect.LIGHTING)) {
                JsonArray lights = new JsonArray();
                List<Light> all = scene.getLights();
                for (int k = 0; k < all.size(); k++) {
                    lights.add(light(k + 1, LightFacts.of(scene, recorded, all.get(k), shader, hit, ray)));
                }
                story.add("lights", lights);
            }
            JsonObject shading = new JsonObject();
            shading.addProperty("shader", ShadingReport.describe(shader));
            shading.add("total", vec(shader.shade(hit, ray, recorded, 0)));
            story.add("shading", shading);
        } catch (RuntimeException | StackOverflowError e) {
            story.addProperty("closestError", "shading threw " + Failure.oneLine(e));
        }
    }

    private JsonObject light(int number, LightFacts f) {
        JsonObject l = new JsonObject();
        l.addProperty("number", number);
        l.add("position", vec(f.light.getPosition()));
        l.add("intensity", vec(f.light.getIntensity()));
        l.add("l", vec(f.l));
        l.add("r", num(Math.sqrt(f.r2)));
        l.add("nDotL", num(f.nl));
        l.addProperty("blocked", f.blocked());
        l.add("shadowRay", JsonNull.INSTANCE);
        l.add("blocker", JsonNull.INSTANCE);
        l.add("shadowError", JsonNull.INSTANCE);
        if (f.shadow != null) {
            JsonObject s = new JsonObject();
            s.add("origin", vec(f.shadow.ray.origin));
            s.add("direction", vec(f.shadow.ray.direction));
            s.add("start", num(f.shadow.ray.start));
            s.add("end", num(f.shadow.ray.end));
            l.add("shadowRay", s);
            ProbeNode b = f.shadow.nearestBlocker();
            if (b != null) {
                JsonObject blocker = new JsonObject();
                blocker.addProperty("path", ProbeTree.path(f.shadow.roots, b, names));
                blocker.add("t", num(b.t()));
                blocker.add("location", vec(b.worldLocation()));
                // A blocker behind the shadow ray's start, as `ray1 trace` flags it, or null.
                String outside = RecordChecks.outsideSegment(b.t(), f.shadow.ray, "shadow ray");
                blocker.add("check", outside == null ? JsonNull.INSTANCE : new JsonPrimitive(outside));
                l.add("blocker", blocker);
            }
            String problem = f.shadow.problem();
            l.add("shadowError", problem == null ? JsonNull.INSTANCE : new JsonPrimitive(problem));
        }
        l.add("diffuse", vec(f.diffuse));
        l.add("specular", vec(f.specular));
        l.add("microfacet", JsonNull.INSTANCE);
        if (f.microfacet != null) {
            MicrofacetTerms m = f.microfacet;
            JsonObject mf = new JsonObject();
            mf.add("h", vec(m.h));
            mf.add("fresnel", num(m.fresnel));
            mf.add("distribution", num(m.distribution));
            mf.add("maskingL", num(m.maskingL));
            mf.add("maskingV", num(m.maskingV));
            mf.add("error", m.error == null ? JsonNull.INSTANCE : new JsonPrimitive(m.error));
            l.add("microfacet", mf);
        }
        l.add("adds", vec(f.adds));
        // The formula's share beside the shader's own, for a light loop of the students' that differs.
        l.add("formula", vec(f.formula()));
        l.addProperty("agreesWithFormula", f.agreesWithFormula());
        return l;
    }
}
