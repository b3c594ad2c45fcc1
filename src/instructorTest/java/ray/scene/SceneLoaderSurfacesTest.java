package ray.scene;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.IntersectionRecord;
import ray.math.Vec3;
import ray.shading.Lambertian;
import ray.surface.Sphere;
import ray.surface.Triangle;

/**
 * Checks that {@code <surface>} of every type (Sphere, Triangle, Box, Mesh, Group with nested
 * surfaces and translate/rotate/scale) is built from its properties, by intersecting rays with the
 * loaded scene and comparing each hit with a hand-computed one.
 */
public class SceneLoaderSurfacesTest {
    private static final double TOL = 1e-9;

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void sphereReadsCenterAndRadius() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <surface type="Sphere">
                    <center>1 2 -5</center>
                    <radius>2</radius>
                  </surface>
                """);
        // From (1, 2, 5) straight down −z to the sphere's near pole: z = −5 + 2 = −3 at t = 8.
        IntersectionRecord hit = hitOrFail(scene, v(1, 2, 5), v(0, 0, -1));
        assertEquals(8, hit.t, TOL);
        assertVec(v(1, 2, -3), hit.location, TOL);
        assertVec(v(0, 0, 1), hit.normal, TOL);
        assertTrue("a " + hit.surface, hit.surface instanceof Sphere);
        // 2.5 off the axis: outside radius 2.
        assertNull(SceneFixtures.hit(scene, v(1, 4.5, 5), v(0, 0, -1)));
    }

    @Test
    public void triangleReadsItsThreeVertices() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <surface type="Triangle">
                    <v0>0 0 -1</v0>
                    <v1>2 0 -1</v1>
                    <v2>0 2 -1</v2>
                  </surface>
                """);
        // (0.5, 0.5) = v0 + 0.25·(v1 − v0) + 0.25·(v2 − v0); normal (v1 − v0) × (v2 − v0) ∥ +z.
        IntersectionRecord hit = hitOrFail(scene, v(0.5, 0.5, 5), v(0, 0, -1));
        assertEquals(6, hit.t, TOL);
        assertVec(v(0.5, 0.5, -1), hit.location, TOL);
        assertVec(v(0, 0, 1), hit.normal, TOL);
        assertEquals(0.25, hit.beta, TOL);
        assertEquals(0.25, hit.gamma, TOL);
        // (1.5, 1.5) has beta + gamma = 1.5 > 1: beyond the hypotenuse.
        assertNull(SceneFixtures.hit(scene, v(1.5, 1.5, 5), v(0, 0, -1)));
    }

    @Test
    public void boxReadsMinAndMaxCornersInAnyCase() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <surface type="Box">
                    <minpt>-1 -2 -3</minpt>
                    <MAXPT>1 2 3</MAXPT>
                  </surface>
                """);
        IntersectionRecord top = hitOrFail(scene, v(0, 0, 10), v(0, 0, -1));
        assertEquals(7, top.t, TOL);
        assertVec(v(0, 0, 3), top.location, TOL);
        assertVec(v(0, 0, 1), top.normal, TOL);
        IntersectionRecord side = hitOrFail(scene, v(10, 1.5, 0), v(-1, 0, 0));
        assertVec(v(1, 1.5, 0), side.location, TOL);
        assertVec(v(1, 0, 0), side.normal, TOL);
        // y = 2.5 is above maxPt.y = 2.
        assertNull(SceneFixtures.hit(scene, v(0, 2.5, 10), v(0, 0, -1)));
    }

    @Test
    public void meshDataIsRelativeToTheSceneFilesFolder() {
        // A unit quad at z = −2 whose face 1 2 3 4 becomes triangles (1, 2, 3) and (1, 3, 4).
        SceneFixtures.write(folder, "meshes/quad.obj", """
                v 0 0 -2
                v 1 0 -2
                v 1 1 -2
                v 0 1 -2
                f 1 2 3 4
                """);
        Path sceneFile = SceneFixtures.write(folder, "scenes/quad.xml", "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE + """
                  <surface type="Mesh">
                    <data>../meshes/quad.obj</data>
                  </surface>
                </scene>
                """);
        Scene scene = SceneLoader.load(sceneFile);
        // Below the diagonal y = x: the first triangle, whose v1 is the quad's second vertex.
        IntersectionRecord lower = hitOrFail(scene, v(0.75, 0.25, 5), v(0, 0, -1));
        assertVec(v(0.75, 0.25, -2), lower.location, TOL);
        assertVec(v(0, 0, 1), lower.normal, TOL);
        assertVec(v(1, 0, -2), ((Triangle) lower.surface).getV1(), 0);
        // Above it: the second triangle, whose v1 is the quad's third vertex.
        IntersectionRecord upper = hitOrFail(scene, v(0.25, 0.75, 5), v(0, 0, -1));
        assertEquals(7, upper.t, TOL);
        assertVec(v(1, 1, -2), ((Triangle) upper.surface).getV1(), 0);
        assertVec(v(0, 1, -2), ((Triangle) upper.surface).getV2(), 0);
    }

    @Test
    public void meshDataMayBeAnAbsolutePathAndBringsVertexNormals() {
        // Every vertex normal is +y, so the shading normal is +y although the face normal is +z.
        Path obj = SceneFixtures.write(folder, "elsewhere/tilted.obj", """
                v 0 0 -2
                v 1 0 -2
                v 0 1 -2
                vn 0 1 0
                f 1//1 2//1 3//1
                """);
        Scene scene = SceneFixtures.loadBody(folder, "  <surface type=\"Mesh\">\n    <data>" + obj.toAbsolutePath()
                + "</data>\n  </surface>\n");
        IntersectionRecord hit = hitOrFail(scene, v(0.25, 0.25, 5), v(0, 0, -1));
        assertVec(v(0.25, 0.25, -2), hit.location, TOL);
        assertVec(v(0, 1, 0), hit.normal, TOL);
    }

    @Test
    public void groupAppliesScaleThenRotationThenTranslation() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <surface type="Group">
                    <translate>5 0 0</translate>
                    <rotate>0 0 90</rotate>
                    <scale>2 1 1</scale>
                    <surface type="Sphere"/>
                  </surface>
                """);
        // T·Rz(90°)·S maps (x, y, z) to (5 − y, 2x, z): the unit sphere becomes an ellipsoid around
        // (5, 0, 0) with semi-axes 1 along x, 2 along y (the scaled axis, rotated) and 1 along z.
        IntersectionRecord fromAbove = hitOrFail(scene, v(5, 10, 0), v(0, -1, 0));
        assertEquals(8, fromAbove.t, TOL);
        assertVec(v(5, 2, 0), fromAbove.location, TOL);
        assertVec(v(0, 1, 0), fromAbove.normal, TOL);
        IntersectionRecord fromRight = hitOrFail(scene, v(10, 0, 0), v(-1, 0, 0));
        assertEquals(4, fromRight.t, TOL);
        assertVec(v(6, 0, 0), fromRight.location, TOL);
        assertVec(v(1, 0, 0), fromRight.normal, TOL);
    }

    @Test
    public void groupRotatesAboutXThenYThenZ() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <surface type="Group">
                    <rotate>90 90 90</rotate>
                    <surface type="Sphere">
                      <center>1 2 3</center>
                      <radius>0.5</radius>
                    </surface>
                  </surface>
                """);
        // Rx(90°): (x, y, z) → (x, −z, y) takes (1, 2, 3) to (1, −3, 2); Ry(90°): (x, y, z) → (z, y, −x)
        // takes it to (2, −3, −1); Rz(90°): (x, y, z) → (−y, x, z) takes it to (3, 2, −1).
        // (The other order, z then y then x, would end at (3, −2, 1).)
        IntersectionRecord hit = hitOrFail(scene, v(3, 2, 10), v(0, 0, -1));
        assertEquals(10.5, hit.t, TOL);
        assertVec(v(3, 2, -0.5), hit.location, TOL);
    }

    @Test
    public void nestedGroupsComposeTheirTranslations() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <surface type="Group">
                    <translate>0 0 -10</translate>
                    <surface type="Group">
                      <translate>1 0 0</translate>
                      <surface type="Sphere">
                        <radius>0.5</radius>
                      </surface>
                    </surface>
                    <surface type="Sphere">
                      <center>-1 0 0</center>
                      <radius>0.5</radius>
                    </surface>
                  </surface>
                """);
        // Inner sphere at (0, 0, −10) + (1, 0, 0); outer group's own sphere at (−1, 0, −10).
        IntersectionRecord inner = hitOrFail(scene, v(1, 0, 0), v(0, 0, -1));
        assertEquals(9.5, inner.t, TOL);
        assertVec(v(1, 0, -9.5), inner.location, TOL);
        IntersectionRecord sibling = hitOrFail(scene, v(-1, 0, 0), v(0, 0, -1));
        assertVec(v(-1, 0, -9.5), sibling.location, TOL);
        assertNull("nothing at the untransformed origin", SceneFixtures.hit(scene, v(0, 0, 5), v(0, 0, -1)));
    }

    @Test
    public void groupShaderGoesToChildrenWithoutTheirOwn() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <shader name="red" type="Lambertian">
                    <diffuseColor>1 0 0</diffuseColor>
                  </shader>
                  <surface type="Group">
                    <shader ref="red"/>
                    <surface type="Sphere">
                      <center>0 0 -5</center>
                    </surface>
                    <surface type="Sphere">
                      <center>3 0 -5</center>
                      <shader type="Lambertian">
                        <diffuseColor>0 1 0</diffuseColor>
                      </shader>
                    </surface>
                  </surface>
                """);
        assertSame(scene.getShaders().get(0), hitOrFail(scene, v(0, 0, 0), v(0, 0, -1)).surface.getShader());
        Lambertian own = (Lambertian) hitOrFail(scene, v(3, 0, 0), v(0, 0, -1)).surface.getShader();
        assertVec(v(0, 1, 0), own.getDiffuseColor(), 0);
    }

    @Test
    public void surfacesWithoutShaderAreWhiteLambertian() {
        Scene scene = SceneFixtures.loadBody(folder, """
                  <surface type="Group">
                    <surface type="Box"/>
                  </surface>
                  <surface type="Triangle">
                    <v0>5 0 -1</v0>
                    <v1>6 0 -1</v1>
                    <v2>5 1 -1</v2>
                  </surface>
                """);
        for (Vec3 origin : new Vec3[] {v(0.5, 0.5, 5), v(5.25, 0.25, 5)}) {
            IntersectionRecord hit = hitOrFail(scene, origin, v(0, 0, -1));
            assertTrue("a " + hit.surface.getShader(), hit.surface.getShader() instanceof Lambertian);
            assertVec(v(1, 1, 1), ((Lambertian) hit.surface.getShader()).getDiffuseColor(), 0);
        }
    }

    private static IntersectionRecord hitOrFail(Scene scene, Vec3 origin, Vec3 direction) {
        IntersectionRecord hit = SceneFixtures.hit(scene, origin, direction);
        assertNotNull("the ray from " + origin + " along " + direction + " hits", hit);
        return hit;
    }
}
