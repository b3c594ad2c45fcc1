package ray.inspect;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.function.DoubleFunction;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.camera.OrthographicCamera;
import ray.math.Affine;
import ray.math.Bounds;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Glazed;
import ray.shading.Lambertian;
import ray.shading.Shader;
import ray.shading.ShadingContext;
import ray.shading.ShadingSteps;
import ray.surface.Box;
import ray.surface.Cylinder;
import ray.surface.Sketch;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Transformed;

/**
 * A surface type and a shader type that the inspection code has never heard of show up in
 * {@code ray1 trace} and on the explore page as they describe themselves, with no edit there; and
 * the framework's own shapes are drawn as they say (a cylinder about the middle of its axis, a
 * turned sphere as its box).
 */
public class NewTypesShowUpTest {
    /** The plane z = 0, hit from either side; it says its name and its box, nothing more. */
    private static class ZSquare extends Surface {
        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            double t = -ray.origin.z / ray.direction.z;
            Vec3 p = ray.pointAt(t);
            if (!(ray.start < t && t < ray.end) || Math.abs(p.x) > 1 || Math.abs(p.y) > 1) {
                return false;
            }
            out.t = t;
            out.location = p;
            out.normal = new Vec3(0, 0, 1);
            out.surface = this;
            return true;
        }

        @Override
        public Bounds bounds() {
            return Bounds.of(new Vec3(-1, -1, 0), new Vec3(1, 1, 0));
        }

        @Override
        public String describe(DoubleFunction<String> number) {
            return "ZSquare of side " + number.apply(2);
        }
    }

    /** The same square, drawn by the explore page as its two triangles. */
    private static final class SketchedZSquare extends ZSquare {
        @Override
        public void sketch(Sketch sketch, Affine toWorld) {
            sketch.triangle(toWorld.applyToPoint(new Vec3(-1, -1, 0)), toWorld.applyToPoint(new Vec3(1, -1, 0)), toWorld.applyToPoint(new Vec3(1, 1, 0)));
            sketch.triangle(toWorld.applyToPoint(new Vec3(-1, -1, 0)), toWorld.applyToPoint(new Vec3(1, 1, 0)), toWorld.applyToPoint(new Vec3(-1, 1, 0)));
        }
    }

    /** A constant color, which says nothing of itself. */
    private static class Flat extends Shader {
        @Override
        public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
            return new Vec3(0.25, 0.5, 0.75);
        }
    }

    /** The same color, naming its parameter and explaining it. */
    private static final class ExplainedFlat extends Flat {
        @Override
        public String describe(DoubleFunction<String> number) {
            return super.describe(number) + ", color " + new Vec3(0.25, 0.5, 0.75).format(number);
        }

        @Override
        public Vec3 explain(IntersectionRecord hit, Ray ray, ShadingSteps steps) {
            steps.line("L = the color, whatever the lights");
            Vec3 color = shade(hit, ray, steps.context(), 0);
            steps.row("L", steps.vec(color));
            return color;
        }
    }

    @Test
    public void anUnknownSurfaceIsTracedByItsNameAndDrawnAsItsBox() {
        Scene scene = oneRayScene(new ZSquare(), new Flat());
        String trace = trace(scene);
        assertTrue(trace, trace.contains("#1 ZSquare of side 2  hit  t = 5  at (0, 0, 0)  ← nearest"));
        JsonObject drawn = onlyShape(scene);
        assertEquals("other", drawn.get("kind").getAsString());
        assertEquals("#1 ZSquare of side 2", drawn.get("name").getAsString());
        assertEquals("[-1.0,-1.0,0.0]", drawn.get("min").toString());
        assertEquals("[1.0,1.0,0.0]", drawn.get("max").toString());
    }

    @Test
    public void anUnknownSurfaceThatSketchesItselfIsDrawnAsItSays() {
        Scene scene = oneRayScene(new Transformed(new SketchedZSquare(), Affine.translation(new Vec3(3, 0, 0))), new Flat());
        JsonArray surfaces = outline(scene).getAsJsonArray("surfaces");
        assertEquals(2, surfaces.size());
        JsonObject first = surfaces.get(0).getAsJsonObject();
        assertEquals("triangle", first.get("kind").getAsString());
        String name = first.get("name").getAsString();
        assertTrue(name, name.startsWith("#1 Transformed") && name.endsWith(" › #1 ZSquare of side 2"));
        // Moved by (3, 0, 0): the corners (−1, −1), (1, −1), (1, 1) become (2, −1), (4, −1), (4, 1).
        assertEquals("[[2.0,-1.0,0.0],[4.0,-1.0,0.0],[4.0,1.0,0.0]]", first.get("vertices").toString());
    }

    @Test
    public void anUnknownShaderIsTracedByItsNameAndResult() {
        String trace = trace(oneRayScene(new ZSquare(), new Flat()));
        assertTrue(trace, trace.contains("Shader Flat\n"));
        assertTrue(trace, trace.contains("(0.25, 0.5, 0.75)   (from its shade method; the trace knows no more of this shader)"));
    }

    @Test
    public void anUnknownShaderThatExplainsItselfIsTracedAsItSays() {
        String trace = trace(oneRayScene(new ZSquare(), new ExplainedFlat()));
        assertTrue(trace, trace.contains("Shader ExplainedFlat, color (0.25, 0.5, 0.75)\n"));
        assertTrue(trace, trace.contains("L = the color, whatever the lights\n"));
        assertTrue(trace, trace.matches("(?s).*\\n\\s+L\\s+\\(0\\.25, 0\\.5, 0\\.75\\)\\n.*"));
    }

    @Test
    public void aGlazeNamesItsIndexAndItsSubstrate() {
        Glazed glazed = new Glazed();
        glazed.setRefractiveIndex(1.33);
        glazed.setSubstrate(new Lambertian(new Vec3(1, 0.5, 0)));
        assertEquals("Glazed, refractive index 1.33, over Lambertian, kd = (1, 0.5, 0)", ShadingReport.describe(glazed));
    }

    @Test
    public void aMovedCylinderIsDrawnAboutTheMiddleOfItsAxis() {
        // Bottom cap at y = 1 (moved up by 1 from y = 0), height 4: the axis runs from y = 1 to 5, its middle at 3.
        Cylinder cylinder = new Cylinder(new Vec3(0, 0, 0), 0.5, 4);
        JsonObject drawn = onlyShape(oneRayScene(new Transformed(cylinder, Affine.translation(new Vec3(0, 1, 0))), new Flat()));
        assertEquals("cylinder", drawn.get("kind").getAsString());
        assertEquals("[0.0,3.0,0.0]", drawn.get("center").toString());
        assertEquals(4, drawn.get("height").getAsDouble(), 0);
    }

    @Test
    public void aTurnedSphereIsDrawnAsItsBoxAndAMovedBoxAsABox() {
        Surface turned = new Transformed(new Sphere(new Vec3(0, 0, 0), 1), Affine.rotation(1, 30));
        assertEquals("other", onlyShape(oneRayScene(turned, new Flat())).get("kind").getAsString());
        Box box = new Box();
        box.setMinPt(new Vec3(0, 0, 0));
        box.setMaxPt(new Vec3(1, 2, 3));
        JsonObject drawn = onlyShape(oneRayScene(new Transformed(box.complete(), Affine.translation(new Vec3(1, 1, 1))), new Flat()));
        assertEquals("box", drawn.get("kind").getAsString());
        assertEquals("[1.0,1.0,1.0]", drawn.get("min").toString());
        assertEquals("[2.0,3.0,4.0]", drawn.get("max").toString());
    }

    /**
     * cylinder.xml, pixel (250, 120): the ray meets the lying cylinder, the one part of a rotated
     * group. The explore page sums up that group as one primitive, not as a triangle.
     */
    @Test
    public void aGroupOfOneCylinderIsSummedUpAsOnePrimitive() throws Exception {
        Scene scene = ray.scene.SceneLoader.load(java.nio.file.Path.of("scenes/cylinder.xml"));
        JsonArray hits = new PixelStory(scene, "cylinder").of(250, 120, null, null).getAsJsonArray("hits");
        JsonObject group = hits.get(3).getAsJsonObject();
        assertEquals(hits.toString(), "1 primitive: 1 hit (nearest t = 6.11785 at #1, at (1.73021, 0.953408, 0.510764)  ← nearest), 0 miss",
                group.get("summary").getAsString());
    }

    /** A 1×1 orthographic view from z = 5 straight down −z, onto {@code surface} shaded by {@code shader}. */
    private static Scene oneRayScene(Surface surface, Shader shader) {
        OrthographicCamera camera = new OrthographicCamera();
        camera.setViewPoint(new Vec3(0, 0, 5));
        camera.complete();
        Scene scene = new Scene();
        scene.setCamera(camera);
        scene.setImage(1, 1);
        surface.setShader(shader);
        scene.addSurface(surface.complete());
        scene.complete();
        return scene;
    }

    private static String trace(Scene scene) {
        StringWriter text = new StringWriter();
        try (PrintWriter out = new PrintWriter(text)) {
            assertNotNull(new PixelTrace(scene, "test scene", false, 0).run(0, 0, out));
        }
        return text.toString();
    }

    private static JsonObject outline(Scene scene) {
        JsonObject json = new JsonObject();
        SceneOutline.of(scene, json);
        return json;
    }

    private static JsonObject onlyShape(Scene scene) {
        JsonArray surfaces = outline(scene).getAsJsonArray("surfaces");
        assertEquals(surfaces.toString(), 1, surfaces.size());
        return surfaces.get(0).getAsJsonObject();
    }
}
