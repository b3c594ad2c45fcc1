package ray.numerics;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static ray.testing.Asserts.v;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.function.Consumer;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.IntersectionRecord;
import ray.camera.PerspectiveCamera;
import ray.image.Image;
import ray.math.Vec3;
import ray.render.Renderer;
import ray.render.SecondaryRays;
import ray.scene.Scene;
import ray.scene.SceneException;
import ray.scene.SceneLoader;
import ray.shading.Glazed;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.surface.Box;
import ray.surface.Group;
import ray.surface.Mesh;
import ray.surface.MeshData;
import ray.surface.Placement;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * NaN and infinite values in scene data. A scene file cannot hold them: NaN, Infinity and numbers
 * beyond the double range (1e999) fail to load with the file, line and column. Surfaces, lights and
 * cameras built in code can; rendering a scene that holds them throws nothing, and a surface made
 * of non-finite numbers is simply never hit: the image is the very same as without it (compared
 * channel by channel on a 24×18 render of a glazed sphere on a ground, so that shadow and
 * reflection rays pass by the bad surface too). Where a setter can tell at once (a NaN radius, a
 * box with NaN corners, a NaN scale), it refuses with a message instead.
 */
public class NonFiniteSceneDataTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private static final double NAN = Double.NaN;
    private static final double INF = Double.POSITIVE_INFINITY;

    /** A glazed sphere on a ground triangle, lit by one light, seen from (0, 1, 4), plus {@code extra}'s additions. */
    private static Image render(Consumer<Scene> extra) {
        Scene scene = new Scene();
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewPoint(v(0, 1, 4));
        camera.setViewDir(v(0, -0.25, -1));
        camera.complete();
        scene.setCamera(camera);
        scene.setImage(24, 18);
        scene.setBackColor(v(0.2, 0.3, 0.4));
        scene.addLight(new Light(v(-3, 5, 4), v(30, 30, 30)));
        Sphere ball = new Sphere(v(0, 1, 0), 1);
        ball.setShader(new Glazed());
        scene.addSurface(ball.complete());
        Triangle ground = new Triangle(v(-50, 0, -50), v(0, 0, 50), v(50, 0, -50));
        ground.setShader(new Lambertian(v(0.6, 0.6, 0.6)));
        scene.addSurface(ground.complete());
        extra.accept(scene);
        scene.complete();
        return new Renderer(scene, 1, 1).render().image;
    }

    private static double[] channels(Image image) {
        double[] c = new double[3 * image.width() * image.height()];
        int k = 0;
        for (int j = 0; j < image.height(); j++) {
            for (int i = 0; i < image.width(); i++) {
                Vec3 p = image.get(i, j);
                c[k++] = p.x;
                c[k++] = p.y;
                c[k++] = p.z;
            }
        }
        return c;
    }

    /** The scene without any bad surface, rendered once on first use (not when the class loads). */
    private static double[] clean;

    private static synchronized double[] clean() {
        if (clean == null) {
            clean = channels(render(scene -> { }));
        }
        return clean;
    }

    private static void assertNeverHit(String what, Surface bad) {
        Image image = render(scene -> scene.addSurface(bad.complete()));
        assertArrayEquals(what + " should be a surface no ray hits", clean(), channels(image), 0);
    }

    @Test
    public void aFiniteSurfaceInTheSamePlaceWouldChangeTheImage() {
        // So that "the same image" above means something: the ball, its shadow and its reflections show.
        Image withSphere = render(scene -> scene.addSurface(new Sphere(v(1.2, 0.5, 1), 0.5).complete()));
        Image withTriangle = render(scene -> scene.addSurface(new Triangle(v(-1, 0.5, 1), v(1, 0.5, 1), v(0, 2, 1))));
        assertFalse(Arrays.equals(clean(), channels(withSphere)));
        assertFalse(Arrays.equals(clean(), channels(withTriangle)));
    }

    @Test
    public void sphereWithNonFiniteCenterIsNeverHit() {
        assertNeverHit("a sphere centered at (NaN, 1, 0)", new Sphere(v(NAN, 1, 0), 0.5));
        assertNeverHit("a sphere centered at (0, ∞, 0)", new Sphere(v(0, INF, 0), 0.5));
        assertNeverHit("a sphere centered at (−∞, −∞, −∞)", new Sphere(v(-INF, -INF, -INF), 0.5));
    }

    @Test
    public void triangleWithNonFiniteVertexIsNeverHit() {
        assertNeverHit("a triangle with a NaN vertex", new Triangle(v(-1, 0.5, 1), v(1, 0.5, 1), v(0, NAN, 1)));
        assertNeverHit("a triangle with an infinite vertex", new Triangle(v(-1, 0.5, 1), v(1, 0.5, 1), v(0, INF, 1)));
        assertNeverHit("a triangle with all vertices infinite", new Triangle(v(INF, INF, INF), v(-INF, INF, 0), v(0, 0, -INF)));
    }

    @Test
    public void meshWithNonFinitePositionsIsNeverHit() {
        Mesh mesh = new Mesh();
        mesh.setData(new MeshData(new double[] {-1, 0.5, 1, 1, 0.5, 1, NAN, NAN, NAN, 0, INF, 1}, null,
                new int[] {0, 1, 2, 0, 1, 3}, null));
        assertNeverHit("a mesh whose triangles each have a NaN or infinite vertex", mesh);
    }

    @Test
    public void groupMovedByAnInfiniteTranslationIsNeverHit() {
        Group group = new Group();
        group.addSurface(new Sphere(v(0, 1, 1.5), 0.3));
        assertNeverHit("a group translated by (∞, 0, 0)", Placement.of(v(INF, 0, 0), Vec3.ZERO, Vec3.ONE).place(group));
    }

    @Test
    public void nonFiniteVertexNormalsFallBackToTheFaceNormal() {
        // A smooth triangle in front of the ball whose vertex normals are NaN: it is hit, and shaded
        // with its face normal (0, 0, 1) rather than with NaN.
        Triangle smooth = new Triangle(v(-0.2, 0.8, 2), v(0.2, 0.8, 2), v(0, 1.2, 2), v(NAN, 0, 1), v(NAN, 0, 1), v(NAN, 0, 1));
        Triangle flat = new Triangle(v(-0.2, 0.8, 2), v(0.2, 0.8, 2), v(0, 1.2, 2));
        assertArrayEquals(channels(render(scene -> scene.addSurface(flat))), channels(render(scene -> scene.addSurface(smooth))), 0);
    }

    @Test
    public void nonFiniteLightsAndCameraRenderWithoutThrowing() {
        // Nothing here can be right, but none of it may stop a render: NaN radiance shows as black.
        render(scene -> scene.addLight(new Light(v(NAN, 1, 1), v(1, 1, 1))));
        render(scene -> scene.addLight(new Light(v(0, 3, 3), v(INF, INF, INF))));
        render(scene -> scene.addLight(new Light(v(INF, 3, 3), v(1, 1, 1))));
        Image image = render(scene -> {
            PerspectiveCamera camera = new PerspectiveCamera();
            camera.setViewPoint(v(NAN, 0, 0));
            camera.complete();
            scene.setCamera(camera);
        });
        // Every camera ray is NaN and hits nothing: the background everywhere.
        for (int j = 0; j < image.height(); j++) {
            for (int i = 0; i < image.width(); i++) {
                assertEquals(v(0.2, 0.3, 0.4), image.get(i, j));
            }
        }
    }

    @Test
    public void hugeButFiniteSphereRendersWithoutThrowing() {
        // r² overflows to ∞ for radius 1e200; the intersection may hit or miss but must not throw.
        render(scene -> scene.addSurface(new Sphere(v(0, -1e200, 0), 1e200)));
        render(scene -> scene.addSurface(new Sphere(v(0, 1, 1.5), 1e-200)));
    }

    @Test
    public void secondaryRaysFromANonFiniteHitDoNotThrow() {
        IntersectionRecord hit = new IntersectionRecord();
        hit.t = 1;
        hit.location = v(NAN, 0, 0);
        hit.normal = v(0, 1, 0);
        hit.surface = new Sphere(v(0, 0, 0), 1);
        SecondaryRays.shadowRay(hit.surface.hitGeometry(hit), v(0, 5, 0));
        SecondaryRays.reflectionRay(hit.surface.hitGeometry(hit), v(0, 1, 0));
        hit.surface = new Triangle(v(0, 0, 0), v(INF, 0, 0), v(0, 0, 1));
        SecondaryRays.shadowRay(hit.surface.hitGeometry(hit), v(0, 5, 0));
    }

    @Test
    public void settersRefuseWhatTheyCanTellIsBroken() {
        assertRefused("radius is NaN; expected a positive number", () -> new Sphere(v(0, 0, 0), NAN));
        assertRefused("radius is Infinity; expected a positive number", () -> new Sphere(v(0, 0, 0), INF));
        Box box = new Box();
        box.setMinPt(v(NAN, 0, 0));
        assertRefused("minPt is (NaN, 0.0, 0.0); expected three finite numbers", box::complete);
        assertRefused("cannot be inverted (its determinant is NaN)", () -> Placement.of(Vec3.ZERO, Vec3.ZERO, v(NAN, 1, 1)).place(new Group()));
    }

    private static void assertRefused(String message, Runnable build) {
        try {
            build.run();
            fail("expected an IllegalArgumentException saying " + message);
        } catch (IllegalArgumentException e) {
            assertTrue(e.getMessage(), e.getMessage().contains(message));
        }
    }

    @Test
    public void sceneFilesCannotHoldNonFiniteNumbers() throws IOException {
        String[][] cases = {
            {"<viewPoint>0 NaN 5</viewPoint>", "\"NaN\" in <viewPoint> is not a number"},
            {"<viewPoint>0 1e999 5</viewPoint>", "\"1e999\" in <viewPoint> is too large"},
            {"<viewPoint>-1e999 0 5</viewPoint>", "\"-1e999\" in <viewPoint> is too large"},
            {"<viewPoint>0 0 Infinity</viewPoint>", "\"Infinity\" in <viewPoint> is not a number"},
        };
        for (String[] c : cases) {
            Path file = folder.getRoot().toPath().resolve("bad.xml");
            Files.writeString(file, "<scene>\n  <camera type=\"PerspectiveCamera\">\n    " + c[0]
                    + "\n  </camera>\n  <image>4 4</image>\n</scene>\n");
            try {
                SceneLoader.load(file);
                fail("loaded a scene with " + c[0]);
            } catch (SceneException e) {
                assertTrue(e.getMessage(), e.getMessage().startsWith(file + ":3:"));
                assertTrue(e.getMessage(), e.getMessage().contains(c[1]));
            }
        }
        for (String light : new String[] {"<position>NaN 1 1</position>", "<intensity>1e400 1 1</intensity>"}) {
            Path file = folder.getRoot().toPath().resolve("light.xml");
            Files.writeString(file, "<scene>\n  <camera type=\"PerspectiveCamera\"/>\n  <image>4 4</image>\n  <light>\n    "
                    + light + "\n  </light>\n</scene>\n");
            try {
                SceneLoader.load(file);
                fail("loaded a scene with " + light);
            } catch (SceneException e) {
                assertTrue(e.getMessage(), e.getMessage().startsWith(file + ":5:"));
            }
        }
    }
}
