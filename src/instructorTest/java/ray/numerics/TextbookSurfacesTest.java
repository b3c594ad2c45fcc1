package ray.numerics;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;

import java.util.List;
import org.junit.Test;
import ray.math.Vec3;
import ray.surface.Box;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * The textbook copies of a scene reach every triangle: a box's (and so a mesh's) triangles are
 * replaced too, not only loose ones, so that the accuracy report's "textbook" and "float" settings
 * and the far-scene comparison test all of a scene's geometry the textbook way.
 */
public class TextbookSurfacesTest {
    @Test
    public void aBoxsTrianglesAreReplacedOneByOne() {
        Box box = new Box();
        box.setMinPt(new Vec3(0, 0, 0));
        box.setMaxPt(new Vec3(1, 2, 3));
        box.complete();
        Surface textbook = TextbookSurfaces.withTriangles(box, TextbookTriangles.CRAMER);
        List<Surface> parts = textbook.children();
        assertEquals(12, parts.size());
        for (Surface part : parts) {
            assertFalse("a box triangle kept the solution's test: " + part, part instanceof Triangle);
            assertEquals(0, part.children().size());
        }
    }
}
