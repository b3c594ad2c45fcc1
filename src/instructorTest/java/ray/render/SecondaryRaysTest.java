package ray.render;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.HitGeometry;
import ray.surface.Sphere;
import ray.surface.Triangle;

/**
 * Where new rays start and end ({@link SecondaryRays}): off the re-projected hit along the
 * geometric normal, on the side the ray leaves to, by OFFSET_ULPS·2⁻⁵³·scale; a shadow ray ends just
 * short of its light. Records are filled by hand, so no student code runs.
 */
public class SecondaryRaysTest {
    /** A hit on the triangle (0,0,0), (4,0,0), (0,4,0) at (1, 1, 0) whose shading normal leans toward +x. */
    private static HitGeometry smoothTriangleHit() {
        Vec3 tilted = v(1, 0, 1).normalized();
        IntersectionRecord hit = new IntersectionRecord();
        hit.t = 1;
        hit.location = v(1, 1, 0);
        hit.normal = tilted;
        hit.surface = new Triangle(v(0, 0, 0), v(4, 0, 0), v(0, 4, 0), tilted, tilted, tilted);
        return hit.surface.hitGeometry(hit);
    }

    // The triangle's scale is 4 (coordinates) × 2 (thinness), so the offset is 1024 · 2⁻⁵³ · 8 = 2⁻⁴⁰.
    private static final double OFFSET = 0x1p-40;

    @Test
    public void offsetIsAFixedMultipleOfEpsilonTimesScale() {
        assertEquals(1024, SecondaryRays.OFFSET_ULPS, 0);
        assertEquals(OFFSET, SecondaryRays.offset(smoothTriangleHit()), 0);
    }

    @Test
    public void rayStartsOnTheSideOfTheGeometricNormalItLeavesTo() {
        // Up and against the shading normal's lean: n_shading · d < 0 but n_face · d > 0, so the
        // ray leaves from above the plane, where it does not cross its own triangle.
        Vec3 d = v(-1, 0, 0.5);
        Ray reflected = SecondaryRays.reflectionRay(smoothTriangleHit(), d);
        assertVec(v(1, 1, OFFSET), reflected.origin, 0);
        assertVec(d, reflected.direction, 0);
        assertEquals(0, reflected.start, 0);
        assertEquals(Double.POSITIVE_INFINITY, reflected.end, 0);
        // Down through the plane: it starts below.
        assertVec(v(1, 1, -OFFSET), SecondaryRays.reflectionRay(smoothTriangleHit(), v(1, 0, -0.5)).origin, 0);
    }

    @Test
    public void shadowRayRunsFromJustOffTheSurfaceToJustShortOfTheLight() {
        IntersectionRecord hit = new IntersectionRecord();
        hit.t = 1;
        hit.location = v(0, 0, 2);
        hit.normal = v(0, 0, 1);
        hit.surface = new Sphere(v(0, 0, 0), 2);
        Vec3 light = v(0, 3, 6);
        Ray shadow = SecondaryRays.shadowRay(hit.surface.hitGeometry(hit), light);
        // Scale 0 + 2 = 2: offset 1024 · 2⁻⁵³ · 2 = 2⁻⁴² along +z.
        assertVec(v(0, 0, 2 + 0x1p-42), shadow.origin, 0);
        assertVec(light, shadow.pointAt(1), 1e-15);
        assertEquals(0, shadow.start, 0);
        assertEquals(SecondaryRays.SHADOW_END, shadow.end, 0);
        assertEquals(1 - 1e-9, SecondaryRays.SHADOW_END, 0);
    }
}
