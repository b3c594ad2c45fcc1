package ray.scene;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertThrows;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.math.Vec3;
import ray.shading.BrdfShader;
import ray.shading.Course;
import ray.shading.MicrofacetBrdf;
import ray.shading.Shader;

/**
 * Microfacet shaders in scene files: the course's 2019 form ({@code MicrofacetBeckmann},
 * {@code MicrofacetGGX}) and the older form (a scene-level {@code <brdf type="Beckmann">} that a
 * {@code Microfacet} shader refers to) load as the 2019 reflection shader with a microfacet BRDF under
 * either course; a missing or bad roughness or index is one line naming the file, line and what was
 * expected; and the course's check value comes through the scene's float numbers to 1e-6.
 */
public class SceneLoaderMicrofacetTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private static String scene(String shaders) {
        return "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE + shaders + "  <surface type=\"Sphere\"><shader ref=\"m\"/></surface>\n</scene>\n";
    }

    private Shader load(String shaders, Course course) {
        return SceneLoader.load(SceneFixtures.write(folder, "m.xml", scene(shaders)), SceneOptions.of(course, null)).getSurfaces()
                .children().get(0).getShader();
    }

    private String error(String shaders) {
        Path file = SceneFixtures.write(folder, "bad.xml", scene(shaders));
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load(file, SceneOptions.of(Course.Y2019, null)));
        assertTrue(e.getMessage(), e.getMessage().startsWith(file.toString() + ":"));
        assertTrue(e.getMessage(), !e.getMessage().contains("\n"));
        return e.getMessage().substring(file.toString().length());
    }

    private static MicrofacetBrdf brdf(Shader shader) {
        assertTrue(shader.getClass().getName(), shader instanceof BrdfShader);
        assertTrue(String.valueOf(((BrdfShader) shader).brdf()), ((BrdfShader) shader).brdf() instanceof MicrofacetBrdf);
        return (MicrofacetBrdf) ((BrdfShader) shader).brdf();
    }

    @Test
    public void theCourses2019FormLoadsUnderEitherCourse() {
        String xml = "  <shader type=\"MicrofacetGGX\" name=\"m\">\n    <diffuseColor>0.1 0.2 0.3</diffuseColor>\n"
                + "    <microfacetColor>0.9 0.8 0.7</microfacetColor>\n    <nt>1.6</nt>\n    <alpha>0.25</alpha>\n"
                + "    <mirrorCoefficient>0.05 0.05 0.05</mirrorCoefficient>\n  </shader>\n";
        for (Course course : Course.values()) {
            Shader shader = load(xml, course);
            MicrofacetBrdf brdf = brdf(shader);
            assertEquals("GGX", brdf.distribution().name());
            assertEquals(0.25, brdf.distribution().getAlpha(), 1e-7);
            assertEquals(1.6, brdf.fresnel().getNt(), 1e-7);
            assertVec(v(0.9, 0.8, 0.7), brdf.getMicrofacetColor(), 1e-7);
            assertVec(v(0.1, 0.2, 0.3), shader.getDiffuseColor(), 1e-7);
            assertVec(v(0.05, 0.05, 0.05), ((BrdfShader) shader).getMirrorCoefficient(), 1e-7);
            assertEquals("MicrofacetGGX", shader.toString());
        }
    }

    @Test
    public void theDefaultsAreNoDiffusePartAndWhiteFacets() {
        Shader shader = load("  <shader type=\"MicrofacetBeckmann\" name=\"m\"><nt>2</nt><alpha>0.7</alpha></shader>\n", Course.Y2019);
        assertVec(Vec3.ZERO, shader.getDiffuseColor(), 0);
        assertVec(Vec3.ONE, brdf(shader).getMicrofacetColor(), 0);
        assertVec(Vec3.ZERO, ((BrdfShader) shader).getMirrorCoefficient(), 0);
    }

    @Test
    public void theOlderFormWithASceneLevelBrdf() {
        Shader shader = load("  <brdf name=\"Beckmann\" type=\"Beckmann\"><nt>2</nt><alpha>0.7</alpha></brdf>\n"
                + "  <shader type=\"Microfacet\" name=\"m\"><brdf ref=\"Beckmann\"/><microfacetColor>.2 .3 .8</microfacetColor></shader>\n",
                Course.Y2019);
        MicrofacetBrdf brdf = brdf(shader);
        assertEquals("Beckmann", brdf.distribution().name());
        assertEquals(0.7, brdf.distribution().getAlpha(), 1e-7);
        assertEquals(2, brdf.fresnel().getNt(), 0);
        assertVec(v(0.2, 0.3, 0.8), brdf.getMicrofacetColor(), 1e-7);
        assertEquals("Microfacet", shader.toString());
    }

    @Test
    public void aMissingOrBadRoughnessOrIndexIsOneLine() {
        assertEquals(":4:41: invalid MicrofacetGGX: no <alpha> (or 0); expected a roughness > 0, such as 0.3",
                error("  <shader type=\"MicrofacetGGX\" name=\"m\"><nt>1.5</nt></shader>\n"));
        assertEquals(":4:46: invalid MicrofacetBeckmann: alpha is -0.5; expected a roughness > 0, such as 0.3",
                error("  <shader type=\"MicrofacetBeckmann\" name=\"m\"><nt>1.5</nt><alpha>-0.5</alpha></shader>\n"));
        assertEquals(":4:41: invalid MicrofacetGGX: nt is -1.0; expected a refractive index > 0, such as 1.5",
                error("  <shader type=\"MicrofacetGGX\" name=\"m\"><nt>-1</nt><alpha>0.3</alpha></shader>\n"));
        assertEquals(":4:41: invalid MicrofacetGGX: no <nt> (or 0); expected a refractive index > 0, such as 1.5",
                error("  <shader type=\"MicrofacetGGX\" name=\"m\"><alpha>0.3</alpha></shader>\n"));
    }

    @Test
    public void theOlderFormNamesWhereItsNumbersBelong() {
        String withoutBrdf = error("  <shader type=\"Microfacet\" name=\"m\"/>\n");
        assertTrue(withoutBrdf, withoutBrdf.contains("no <brdf>; expected <brdf ref=\"…\"/> naming a scene-level <brdf type=\"Beckmann\">"));
        String alphaHere = error("  <brdf name=\"b\" type=\"GGX\"><nt>2</nt><alpha>0.7</alpha></brdf>\n"
                + "  <shader type=\"Microfacet\" name=\"m\"><brdf ref=\"b\"/><alpha>0.3</alpha></shader>\n");
        assertTrue(alphaHere, alphaHere.contains("takes its alpha from the <brdf> it refers to; give <alpha> there"));
        String unknown = error("  <brdf name=\"b\" type=\"Beckman\"><nt>2</nt><alpha>0.7</alpha></brdf>\n");
        assertTrue(unknown, unknown.contains("unknown type \"Beckman\" for <brdf> (did you mean \"Beckmann\"?); expected one of Beckmann, GGX"));
    }

    /** The course's check point through a scene's float numbers: α = 0.5 and nt = 1.5 are exact in float, so f is the check value to 1e-6 (and closer). */
    @Test
    public void theCoursesCheckValueThroughTheScenesNumbers() {
        Shader shader = load("  <shader type=\"MicrofacetBeckmann\" name=\"m\"><diffuseColor>1 1 1</diffuseColor>"
                + "<nt>1.5</nt><alpha>0.5</alpha></shader>\n", Course.Y2019);
        Vec3 l = v(Math.sin(Math.toRadians(60)), 0, Math.cos(Math.toRadians(60)));
        Vec3 view = v(Math.sin(Math.toRadians(-30)), 0, Math.cos(Math.toRadians(-30)));
        Vec3 f = brdf(shader).value(shader.getDiffuseColor(), v(0, 0, 1), l, view);
        assertVec(v(0.3498099620956212, 0.3498099620956212, 0.3498099620956212), f, 1e-6);
    }
}
