package ray.scene;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.shading.Glazed;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.shading.Phong;
import ray.shading.RGBNormals;
import ray.shading.Shader;
import ray.shading.ShadingContext;
import ray.surface.Sphere;
import ray.surface.Surface;

/**
 * Checks {@code <shader>} of every type: defined at the top level with a name and reused by
 * {@code <shader ref>}, defined inline in a surface, Glazed with its substrate inline or by ref, and
 * the white Lambertian that a surface without a shader gets. Phong has no getters, so its properties
 * are checked through the radiance it computes for a hand-worked configuration.
 */
public class SceneLoaderShadersTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void namedShaderIsSharedBySurfacesThatRefIt() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <shader name="blue" type="Lambertian">
                    <diffuseColor>0.2 0.3 0.8</diffuseColor>
                  </shader>
                  <surface type="Sphere">
                    <shader ref="blue"/>
                    <center>0 0 -5</center>
                  </surface>
                  <surface type="Sphere">
                    <shader ref="blue"/>
                    <center>3 0 -5</center>
                  </surface>
                """);
        assertEquals(1, scene.getShaders().size());
        Shader blue = scene.getShaders().get(0);
        assertTrue("a " + blue, blue instanceof Lambertian);
        assertVec(v(0.2, 0.3, 0.8), ((Lambertian) blue).getDiffuseColor(), 0);
        assertSame(blue, shaderOfSphereAt(scene, v(0, 0, -5)));
        assertSame(blue, shaderOfSphereAt(scene, v(3, 0, -5)));
    }

    @Test
    public void inlineShaderBelongsToItsSurfaceOnly() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <surface type="Sphere">
                    <shader type="Lambertian">
                      <diffuseColor>1 0 0</diffuseColor>
                    </shader>
                    <center>0 0 -5</center>
                  </surface>
                  <surface type="Sphere">
                    <center>3 0 -5</center>
                  </surface>
                """);
        assertTrue("inline shaders are not scene shaders", scene.getShaders().isEmpty());
        Shader red = shaderOfSphereAt(scene, v(0, 0, -5));
        assertVec(v(1, 0, 0), ((Lambertian) red).getDiffuseColor(), 0);
        // The second sphere has no shader: it gets the default white Lambertian.
        Shader white = shaderOfSphereAt(scene, v(3, 0, -5));
        assertTrue("a " + white, white instanceof Lambertian);
        assertVec(v(1, 1, 1), ((Lambertian) white).getDiffuseColor(), 0);
    }

    @Test
    public void phongReadsDiffuseSpecularAndExponent() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <shader name="shiny" type="Phong">
                    <diffuseColor>0.2 0.4 0.6</diffuseColor>
                    <specularColor>0.5 0.25 1</specularColor>
                    <exponent>4</exponent>
                  </shader>
                """);
        Shader phong = scene.getShaders().get(0);
        assertTrue("a " + phong, phong instanceof Phong);
        // Hit at the origin with normal +z, seen from +z, light (1, 1, 1) at (2, 0, 2): r² = 8,
        // n·l = cos 45° = √½, and h bisects l and e = +z, so n·h = cos 22.5° and (n·h)⁴ = ((1 + cos 45°)/2)².
        double diffuse = Math.sqrt(0.5);
        double specular = Math.pow((1 + Math.sqrt(0.5)) / 2, 2);
        Vec3 expected = v(0.2 * diffuse + 0.5 * specular, 0.4 * diffuse + 0.25 * specular, 0.6 * diffuse + specular).times(1.0 / 8);
        assertVec(expected, shadeAtOrigin(phong, new Light(v(2, 0, 2), v(1, 1, 1))), 1e-12);
    }

    @Test
    public void phongWithoutPropertiesIsWhiteWithExponentOne() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <shader name="plain" type="Phong"/>
                """);
        // As above with kd = ks = 1 and exponent 1: (cos 45° + cos 22.5°)/8, cos 22.5° = √((1 + cos 45°)/2).
        double expected = (Math.sqrt(0.5) + Math.sqrt((1 + Math.sqrt(0.5)) / 2)) / 8;
        Vec3 radiance = shadeAtOrigin(scene.getShaders().get(0), new Light(v(2, 0, 2), v(1, 1, 1)));
        assertVec(v(expected, expected, expected), radiance, 1e-12);
    }

    @Test
    public void rgbNormalsShowsTheNormalAsAColor() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <surface type="Sphere">
                    <shader type="RGBNormals"/>
                    <center>0 0 -5</center>
                  </surface>
                """);
        Shader shader = shaderOfSphereAt(scene, v(0, 0, -5));
        assertTrue("a " + shader, shader instanceof RGBNormals);
        // A hit with normal +z: color (n + 1)/2 = (0.5, 0.5, 1).
        assertVec(v(0.5, 0.5, 1), shadeAtOrigin(shader), 1e-12);
    }

    @Test
    public void glazedTakesAnInlineSubstrate() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <shader name="glaze" type="Glazed">
                    <refractiveIndex>1.8</refractiveIndex>
                    <substrate type="Lambertian">
                      <diffuseColor>0.1 0.2 0.3</diffuseColor>
                    </substrate>
                  </shader>
                """);
        Glazed glazed = (Glazed) scene.getShaders().get(0);
        assertEquals(1.8, glazed.getRefractiveIndex(), 0);
        assertTrue("a " + glazed.getSubstrate(), glazed.getSubstrate() instanceof Lambertian);
        assertVec(v(0.1, 0.2, 0.3), ((Lambertian) glazed.getSubstrate()).getDiffuseColor(), 0);
    }

    @Test
    public void glazedTakesASubstrateByRef() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <shader name="matte" type="Phong">
                    <exponent>20</exponent>
                  </shader>
                  <shader name="glaze" type="Glazed">
                    <substrate ref="matte"/>
                  </shader>
                  <surface type="Sphere">
                    <shader ref="glaze"/>
                    <center>0 0 -5</center>
                  </surface>
                """);
        List<Shader> shaders = scene.getShaders();
        assertEquals(2, shaders.size());
        Glazed glazed = (Glazed) shaders.get(1);
        assertSame(shaders.get(0), glazed.getSubstrate());
        assertEquals("the default refractive index", 1.5, glazed.getRefractiveIndex(), 0);
        assertSame(glazed, shaderOfSphereAt(scene, v(0, 0, -5)));
    }

    @Test
    public void glazedWithoutSubstrateIsOverWhiteLambertian() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <shader name="glaze" type="Glazed"/>
                """);
        Shader substrate = ((Glazed) scene.getShaders().get(0)).getSubstrate();
        assertTrue("a " + substrate, substrate instanceof Lambertian);
        assertVec(v(1, 1, 1), ((Lambertian) substrate).getDiffuseColor(), 0);
    }

    /**
     * The shader of the scene's sphere centered at {@code center}, found in the scene's surface list
     * rather than by a ray, so that this test needs no student code.
     */
    private static Shader shaderOfSphereAt(Scene scene, Vec3 center) {
        for (Surface surface : scene.getSurfaces().children()) {
            if (surface instanceof Sphere && ((Sphere) surface).getCenter().equals(center)) {
                return surface.getShader();
            }
        }
        throw new AssertionError("the scene has no sphere centered at " + center);
    }

    /** The radiance a shader gives at the origin, normal +z, seen from (0, 0, 1), nothing shadowed. */
    private static Vec3 shadeAtOrigin(Shader shader, Light... lights) {
        IntersectionRecord hit = new IntersectionRecord();
        hit.t = 1;
        hit.location = v(0, 0, 0);
        hit.normal = v(0, 0, 1);
        ShadingContext shading = new ShadingContext() {
            @Override
            public List<Light> lights() {
                return List.of(lights);
            }

            @Override
            public boolean unoccluded(IntersectionRecord h, Vec3 lightPosition) {
                return true;
            }

            @Override
            public Vec3 radiance(IntersectionRecord h, Vec3 direction, int depth) {
                return Vec3.ZERO;
            }
        };
        return shader.shade(hit, new Ray(v(0, 0, 1), v(0, 0, -1)), shading, 0);
    }
}
