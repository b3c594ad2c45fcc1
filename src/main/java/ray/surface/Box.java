package ray.surface;

import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleFunction;
import ray.math.Affine;
import ray.math.Vec3;

/**
 * An axis-aligned box with corners {@code minPt} and {@code maxPt}, made of two triangles per face.
 *
 * <p>The box is built from the two corners as given, as the course's renderer builds it: its eight
 * corners take minPt or maxPt on each axis, and the face in the plane x = minPt.x is the −x face,
 * whose normal is (−1, 0, 0), the face at x = maxPt.x the +x face with (+1, 0, 0), and likewise in
 * y and z. When minPt is below maxPt on every axis these are the outward normals. When minPt is
 * above maxPt on an axis, that axis's two faces swap places and so point inward (the top face of a
 * box given with minPt.y above maxPt.y has normal (0, −1, 0)), while the other faces still point
 * outward. Each face's triangles are wound so that their geometric normal,
 * (v1 − v0) × (v2 − v0), is exactly that axis.
 *
 * <p>A box flat on one axis (minPt equal to maxPt there) is a rectangle: its four side faces have
 * no area and are left out, and of its two coinciding faces only the minus one is kept (see
 * {@link #complete()}). A box flat on two or three axes is a segment or a point: it has no
 * triangles, and nothing can hit it. Such boxes load with a warning ({@link #warnings()}).
 */
public class Box extends TriangleSet implements WarnsOnLoad {
    /**
     * The faces, in the order the triangles are listed: −x, +x, −y, +y, −z, +z. Corner k takes x from
     * bit 0, y from bit 1 and z from bit 2 of k (0 for minPt, 1 for maxPt); each face is a quad
     * a, b, c, d, counter-clockwise seen from outside when minPt is below maxPt on every axis.
     */
    private static final int[][] FACES = {
        {0, 4, 6, 2}, // −x
        {1, 3, 7, 5}, // +x
        {0, 1, 5, 4}, // −y
        {2, 6, 7, 3}, // +y
        {0, 2, 3, 1}, // −z
        {4, 5, 7, 6}, // +z
    };

    private Vec3 minPt = Vec3.ZERO;
    private Vec3 maxPt = Vec3.ONE;

    public void setMinPt(Vec3 minPt) {
        this.minPt = minPt;
    }

    public void setMaxPt(Vec3 maxPt) {
        this.maxPt = maxPt;
    }

    public Vec3 getMinPt() {
        return minPt;
    }

    public Vec3 getMaxPt() {
        return maxPt;
    }

    /**
     * Builds the triangles from the corners as given (see the class comment), two per face, each
     * face's wound so that its normal is the face's axis.
     *
     * <p>The winding follows from the signs of the two axes a face spans: the quads of {@link #FACES}
     * face outward for a box whose extent is positive on every axis, and an inverted extent on one of
     * the two axes mirrors the face in its own plane, which turns its normal around, so the quad is
     * then walked the other way. (An inverted extent on the face's own axis only moves the face; its
     * normal stays.)
     *
     * <p>A flat axis (minPt equal to maxPt): the faces that span it have no area. They are left out
     * rather than kept as degenerate triangles, which no ray hits exactly and which would only go
     * through the student's {@code Triangle.intersect}, where a zero determinant may give a NaN hit.
     * The flat axis's own two faces lie in one plane; only its minus face is kept, because the course's
     * renderer lists the minus face first and, at an equal distance, the first hit found wins: it
     * always shows the minus face, and keeping that face alone gives the same image whatever the
     * rounding of the two faces' hits.
     *
     * @throws IllegalArgumentException when a corner is not finite
     */
    @Override
    public Surface complete() {
        if (!minPt.isFinite()) {
            throw new IllegalArgumentException("minPt is " + minPt + "; expected three finite numbers");
        }
        if (!maxPt.isFinite()) {
            throw new IllegalArgumentException("maxPt is " + maxPt + "; expected three finite numbers");
        }
        Vec3[] c = new Vec3[8];
        for (int k = 0; k < 8; k++) {
            c[k] = new Vec3((k & 1) == 0 ? minPt.x : maxPt.x, (k & 2) == 0 ? minPt.y : maxPt.y, (k & 4) == 0 ? minPt.z : maxPt.z);
        }
        List<Triangle> built = new ArrayList<>();
        for (int f = 0; f < FACES.length; f++) {
            int axis = f / 2;
            boolean plusFace = f % 2 == 1;
            int across = extentSign((axis + 1) % 3) * extentSign((axis + 2) % 3);
            if (across == 0 || plusFace && extentSign(axis) == 0) {
                continue; // no area, or the flat axis's plus face, which coincides with its minus face
            }
            int[] q = FACES[f];
            if (across > 0) {
                built.add(new Triangle(c[q[0]], c[q[1]], c[q[2]]));
                built.add(new Triangle(c[q[0]], c[q[2]], c[q[3]]));
            } else {
                built.add(new Triangle(c[q[0]], c[q[3]], c[q[2]]));
                built.add(new Triangle(c[q[0]], c[q[2]], c[q[1]]));
            }
        }
        setTriangles(built);
        return this;
    }

    /** +1 where minPt is below maxPt on {@code axis}, −1 where it is above, 0 where they are equal (−0.0 equals 0.0). */
    private int extentSign(int axis) {
        double min = minPt.get(axis);
        double max = maxPt.get(axis);
        return min < max ? 1 : min > max ? -1 : 0;
    }

    /**
     * One line when minPt is not below maxPt on every axis: which axes are inverted or flat, and
     * what was built, e.g. "Box minPt.y > maxPt.y; built from the corners as given, as the course's
     * renderer does". Empty for an ordinary box.
     */
    @Override
    public List<String> warnings() {
        List<String> axes = new ArrayList<>();
        int flat = 0;
        for (int axis = 0; axis < 3; axis++) {
            int sign = extentSign(axis);
            if (sign <= 0) {
                char a = "xyz".charAt(axis);
                axes.add("minPt." + a + (sign < 0 ? " > " : " = ") + "maxPt." + a);
                flat += sign == 0 ? 1 : 0;
            }
        }
        if (axes.isEmpty()) {
            return List.of();
        }
        String which = axes.size() == 1 ? axes.get(0)
                : String.join(", ", axes.subList(0, axes.size() - 1)) + " and " + axes.get(axes.size() - 1);
        String built = flat == 0 ? ""
                : flat == 1 ? " (a flat box)"
                : flat == 2 ? " (a line segment, which no ray hits)"
                : " (a point, which no ray hits)";
        return List.of("Box " + which + built + "; " + (flat >= 2 ? "it has no faces to draw"
                : "built from the corners as given, as the course's renderer does"));
    }

    /**
     * The same box in the frame at {@code origin}: both corners moved and the triangles built anew
     * from them, so an inverted box stays the same inverted box. Where moving would change the
     * corners' order on an axis (rounding an extent thinner than a double can tell apart at the
     * camera's distance to zero; rounding never reverses an order) or overflow, the box is kept as it
     * is, placed by a translation.
     */
    @Override
    public Surface inFrameAt(Vec3 origin) {
        Box moved = new Box();
        moved.setMinPt(minPt.minus(origin));
        moved.setMaxPt(maxPt.minus(origin));
        boolean sameOrder = moved.minPt.isFinite() && moved.maxPt.isFinite();
        for (int axis = 0; axis < 3; axis++) {
            sameOrder &= moved.extentSign(axis) == extentSign(axis);
        }
        if (!sameOrder) {
            return super.inFrameAt(origin);
        }
        moved.setShader(getShader());
        return moved.complete();
    }

    @Override
    public String toString() {
        return "Box[" + minPt + " to " + maxPt + "]";
    }

    /** A box that is only moved stays an axis-aligned box; one turned or scaled is drawn as its triangles. */
    @Override
    public void sketch(Sketch sketch, Affine toWorld) {
        if (toWorld.isTranslation()) {
            sketch.box(toWorld.applyToPoint(getMinPt()), toWorld.applyToPoint(getMaxPt()));
        } else {
            super.sketch(sketch, toWorld);
        }
    }

    @Override
    public String describe(DoubleFunction<String> number) {
        return "Box " + ShapeFacts.vec(getMinPt(), number) + " to " + ShapeFacts.vec(getMaxPt(), number);
    }

    /** "triangle #8 (+y face)": a box's triangle with the face it belongs to. */
    @Override
    public String partName(Surface part, int index) {
        String name = super.partName(part, index);
        Vec3 n = index >= 0 && index < triangleCount() ? triangles().get(index).getFaceNormal() : null;
        if (n == null) {
            return name;
        }
        int axis = Math.abs(n.x) >= Math.abs(n.y) && Math.abs(n.x) >= Math.abs(n.z) ? 0 : Math.abs(n.y) >= Math.abs(n.z) ? 1 : 2;
        return name + " (" + (n.get(axis) > 0 ? "+" : "−") + "xyz".charAt(axis) + " face)";
    }
}
