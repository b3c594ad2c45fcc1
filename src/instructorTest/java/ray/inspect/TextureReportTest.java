package ray.inspect;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.image.Image;
import ray.math.Vec3;
import ray.shading.Texture;
import ray.surface.Sphere;

/**
 * What {@code ray1 trace} says of a texture lookup: the hit's (u, v), the texel the convention
 * picks, its color, and a flag when the texture returns another color. Uses textures defined here,
 * not the student's, so it runs the same before and after Task 5.
 */
public class TextureReportTest {

    /** A 4×2 image whose texel (i, j), j counted from the bottom, has the 8-bit color (10·i, 100·j, 7). */
    private static Image distinctTexels() {
        Image image = new Image(4, 2);
        for (int j = 0; j < 2; j++) {
            for (int i = 0; i < 4; i++) {
                image.set(i, j, v(10 * i / 255.0, 100 * j / 255.0, 7 / 255.0));
            }
        }
        return image;
    }

    /** The course's lookup with Repeat's wrap, written out for the test (image.get counts rows from the bottom). */
    private static final class NearestTexel extends Texture {
        NearestTexel() {
            super(distinctTexels());
        }

        @Override
        public Vec3 getTexColor(double u, double v) {
            return image.get(Math.floorMod((int) (u * 4 + 0.5), 4), 1 - Math.floorMod((int) ((1 - v) * 2 + 0.5), 2));
        }
    }

    /** What the handout's getTexColor returns before Task 5. */
    private static final class StubTexture extends Texture {
        StubTexture() {
            super(distinctTexels());
        }

        @Override
        public Vec3 getTexColor(double u, double v) {
            return Vec3.ZERO;
        }
    }

    private static IntersectionRecord hitAt(double u, double v) {
        IntersectionRecord hit = new IntersectionRecord();
        hit.texU = u;
        hit.texV = v;
        return hit;
    }

    private static String report(Texture texture, IntersectionRecord hit) {
        StringWriter text = new StringWriter();
        try (PrintWriter out = new PrintWriter(text)) {
            TextureReport.explain(texture, hit, "", out);
        }
        return text.toString();
    }

    /**
     * u·4 + ½ = 1.7 and (1 − v)·2 + ½ = 0.7 (v = 0.9 as a float): column 1 of row 0, the file's top
     * row, which is j = 1 from the bottom; 8-bit (10, 100, 7).
     */
    @Test
    public void texelInsideTheImageIsNamedWithItsFileRowAndColor() {
        String out = report(new NearestTexel(), hitAt(0.3, 0.9));
        assertTrue(out, out.contains("(u, v)       (0.3, 0.9)"));
        assertTrue(out, out.contains("texel        (1, 0) of 4×2   (column (int) (u·4 + ½) = (int) 1.7, row (int) ((1 − v)·2 + ½) ="
                + " (int) 0.7; rows count from the image file's top)"));
        assertTrue(out, out.contains("its color    (10, 100, 7)  #0A6407 in the file, / 255 = (0.0392157, 0.392157, 0.027451)"));
        assertTrue(out, out.contains("kd           (0.0392157, 0.392157, 0.027451)   (NearestTexel.getTexColor(u, v))"));
        assertFalse(out, out.contains("!"));
    }

    @Test
    public void aLookupThatReturnsAnotherColorIsFlaggedAsTask5() {
        String out = report(new StubTexture(), hitAt(0.3, 0.9));
        assertTrue(out, out.contains("!            StubTexture.getTexColor returned (0, 0, 0), not that texel's color:"
                + " black, which this texel is not: is it still the stub? See TODO(Task 5)"));
    }

    /** A lookup written out with one mistake: rows not flipped, columns mirrored, or rounded twice. */
    private static final class WrongLookup extends Texture {
        private final String mistake;

        WrongLookup(String mistake) {
            super(distinctTexels());
            this.mistake = mistake;
        }

        @Override
        public Vec3 getTexColor(double u, double v) {
            int column = (int) (u * 4 + 0.5);
            int rowFromTop = (int) ((1 - v) * 2 + 0.5);
            switch (mistake) {
                case "rows":
                    return image.get(column, rowFromTop); // image.get counts from the bottom: the row is not flipped
                case "columns":
                    return image.get(3 - column, 1 - rowFromTop);
                default:
                    return image.get((int) Math.round(u * 4 + 0.5), 1 - rowFromTop); // rounds twice
            }
        }
    }

    /** (0.3, 0.9) picks texel (1, 0), 8-bit (10, 100, 7); its mirrored row's texel (1, 1) is (10, 0, 7). */
    @Test
    public void aTexelOfTheMirroredRowIsNamedAsFlippedRows() {
        String out = report(new WrongLookup("rows"), hitAt(0.3, 0.9));
        assertTrue(out, out.contains("not that texel's color: that is texel (1, 1), the same column in the mirrored row:"
                + " are the rows flipped?"));
        assertFalse(out, out.contains("stub"));
    }

    @Test
    public void aTexelOfTheMirroredColumnIsNamedAsSuch() {
        String out = report(new WrongLookup("columns"), hitAt(0.3, 0.9));
        assertTrue(out, out.contains("that is texel (2, 0), the same row in the mirrored column"));
    }

    /** (0.05, 0.9): (int) (0.2 + ½) = column 0, but Math.round(0.2 + ½) = Math.round(0.7) = column 1, a neighbour. */
    @Test
    public void aNeighbouringTexelPointsAtTheRounding() {
        String out = report(new WrongLookup("round twice"), hitAt(0.05, 0.9));
        assertTrue(out, out.contains("that is the neighbouring texel (1, 0), one column to the right: is u·W or (1 − v)·H rounded"
                + " another way"));
    }

    /**
     * One column of 8 rows, colored so that the row a lookup one row off reads (5) has the color of
     * the mirrored row (1): matching colors would call it a mirror; its index says one row above.
     */
    private static final class OneRowOff extends Texture {
        OneRowOff() {
            super(rowsSharingColors());
        }

        private static Image rowsSharingColors() {
            Image image = new Image(1, 8);
            for (int row = 0; row < 8; row++) {
                double gray = row == 1 || row == 5 ? 40 / 255.0 : row * 20 / 255.0 + 0.5;
                image.set(0, 7 - row, v(gray, gray, gray));
            }
            return image;
        }

        /** H − 1 − (int) (v·H + ½): the rows flipped after the rounding. */
        @Override
        public Vec3 getTexColor(double u, double v) {
            int h = image.height();
            return texel(0, h - 1 - (int) (v * h + 0.5));
        }
    }

    /** v = 0.3: the course's row is (int) (0.7·8 + ½) = 6; the lookup reads 8 − 1 − (int) (2.4 + ½) = 5; the mirrored row is 1. */
    @Test
    public void aLookupOneRowOffIsNamedByTheRowItReadNotByItsColor() {
        String out = report(new OneRowOff(), hitAt(0.3, 0.3));
        assertTrue(out, out.contains("texel        (0, 6) of 1×8"));
        assertTrue(out, out.contains("that is texel (0, 5), one row above: flipping after the rounding, H − 1 − (int) (v·H + ½),"
                + " is one row off everywhere"));
        assertFalse(out, out.contains("mirrored"));
    }

    /** Outside the image the trace gives no verdict, but shows which texel the lookup read there. */
    @Test
    public void outsideTheImageTheTexelTheLookupReadIsShown() {
        String out = report(new NearestTexel(), hitAt(1.2, 0.25));
        assertTrue(out, out.contains("read         texel (1, 0)   (the one NearestTexel.getTexColor reads there)"));
    }

    /**
     * u·4 + ½ = 5.3 and (1 − 0.25)·2 + ½ = 2: column 5 and row 2 of a 4×2 image, which only wrapping
     * or clamping can answer.
     */
    @Test
    public void texelOutsideTheImageIsLeftToRepeatOrClamp() {
        String out = report(new StubTexture(), hitAt(1.2, 0.25));
        assertTrue(out, out.contains("texel        (5, 2) before it is brought into the 4×2 image (column (int) (u·4 + ½) = (int) 5.3,"
                + " row (int) ((1 − v)·2 + ½) = (int) 2): a RepeatTexture wraps it, a ClampTexture clamps it"));
        assertFalse("no verdict outside the image", out.contains("!"));
    }

    /** (0, 0) on a sphere is the south pole: more likely coordinates never set than a hit exactly there. */
    @Test
    public void zeroCoordinatesOnASphereSuggestTask2() {
        IntersectionRecord hit = hitAt(0, 0);
        hit.surface = new Sphere();
        String out = report(new NearestTexel(), hit);
        assertTrue(out, out.contains("set by Sphere.intersect"));
        assertTrue(out, out.contains("(0, 0) is the sphere's south pole: does Sphere.intersect set texU and texV? See TODO(Task 2)"));
        assertEquals(out, 1, out.split("!", -1).length - 1);
    }
}
