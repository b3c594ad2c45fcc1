package ray.math;

/**
 * An affine map p ↦ A·p + b of 3D space (a 4×4 matrix whose last row is 0 0 0 1), used to place
 * a group's children. Points get the translation, vectors do not, and normals use the inverse
 * transpose of A so that they stay perpendicular to transformed surfaces.
 */
public final class Affine {
    public static final Affine IDENTITY = new Affine(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, Vec3.ZERO);

    /** Row-major 3×3 linear part. */
    private final double[] a;
    private final Vec3 b;

    private Affine(double[] linear, Vec3 translation) {
        this.a = linear;
        this.b = translation;
    }

    /** The map with row-major linear part {@code linear} (9 numbers, copied) and translation {@code translation}. */
    public static Affine of(double[] linear, Vec3 translation) {
        if (linear.length != 9) {
            throw new IllegalArgumentException("a linear part of " + linear.length + " numbers; expected 9");
        }
        return new Affine(linear.clone(), translation);
    }

    /** The linear part, row-major (a copy). */
    public double[] linear() {
        return a.clone();
    }

    /** The translation. */
    public Vec3 translationPart() {
        return b;
    }

    public static Affine translation(Vec3 t) {
        return new Affine(IDENTITY.a, t);
    }

    public static Affine scale(Vec3 s) {
        return new Affine(new double[] {s.x, 0, 0, 0, s.y, 0, 0, 0, s.z}, Vec3.ZERO);
    }

    /** Rotation by {@code degrees} about the coordinate axis {@code axis} (0 = x, 1 = y, 2 = z), right-handed. */
    public static Affine rotation(int axis, double degrees) {
        double r = Math.toRadians(degrees);
        double c = Math.cos(r);
        double s = Math.sin(r);
        // Exact values at multiples of 90°, so that rotated boxes keep exactly axis-aligned faces.
        if (degrees % 90 == 0) {
            c = Math.rint(c);
            s = Math.rint(s);
        }
        switch (axis) {
            case 0:
                return new Affine(new double[] {1, 0, 0, 0, c, -s, 0, s, c}, Vec3.ZERO);
            case 1:
                return new Affine(new double[] {c, 0, s, 0, 1, 0, -s, 0, c}, Vec3.ZERO);
            case 2:
                return new Affine(new double[] {c, -s, 0, s, c, 0, 0, 0, 1}, Vec3.ZERO);
            default:
                throw new IllegalArgumentException("axis must be 0, 1 or 2");
        }
    }

    /**
     * A bound, per coordinate, on the error of {@code applyToPoint(p)} for a point p known within
     * {@code error} per coordinate: each output coordinate Σ_j m_ij·p_j + b_i is three products and
     * three sums, so γ(3)·(Σ_j |m_ij·p_j| + |b_i|) of its own rounding, plus (1 + γ(3))·Σ_j |m_ij|·error_j
     * carried from the input (pbrt-v4's transform of a point with error, §6.8.5).
     */
    public Vec3 pointError(Vec3 p, Vec3 error) {
        double g3 = 3 * 0x1p-53 / (1 - 3 * 0x1p-53);
        double[] in = {p.x, p.y, p.z};
        double[] err = {error.x, error.y, error.z};
        double[] bs = {b.x, b.y, b.z};
        double[] out = new double[3];
        for (int r = 0; r < 3; r++) {
            double own = Math.abs(bs[r]);
            double carried = 0;
            for (int c = 0; c < 3; c++) {
                own += Math.abs(a[3 * r + c] * in[c]);
                carried += Math.abs(a[3 * r + c]) * err[c];
            }
            out[r] = g3 * own + (1 + g3) * carried;
        }
        return new Vec3(out[0], out[1], out[2]);
    }

    /** |M|·v: how far a displacement of at most v_j per coordinate can move a point through this map, per coordinate. */
    public Vec3 linearBound(Vec3 v) {
        return new Vec3(Math.abs(a[0]) * v.x + Math.abs(a[1]) * v.y + Math.abs(a[2]) * v.z,
                Math.abs(a[3]) * v.x + Math.abs(a[4]) * v.y + Math.abs(a[5]) * v.z,
                Math.abs(a[6]) * v.x + Math.abs(a[7]) * v.y + Math.abs(a[8]) * v.z);
    }

    /** The map "first {@code inner}, then this". */
    public Affine after(Affine inner) {
        double[] m = new double[9];
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                m[3 * r + c] = a[3 * r] * inner.a[c] + a[3 * r + 1] * inner.a[3 + c] + a[3 * r + 2] * inner.a[6 + c];
            }
        }
        return new Affine(m, applyToVector(inner.b).plus(b));
    }

    public Vec3 applyToPoint(Vec3 p) {
        return applyToVector(p).plus(b);
    }

    public Vec3 applyToVector(Vec3 v) {
        return new Vec3(
                a[0] * v.x + a[1] * v.y + a[2] * v.z,
                a[3] * v.x + a[4] * v.y + a[5] * v.z,
                a[6] * v.x + a[7] * v.y + a[8] * v.z);
    }

    /** Multiplies by the transpose of the linear part: with {@code inverse()} this maps normals. */
    public Vec3 applyTransposeToVector(Vec3 v) {
        return new Vec3(
                a[0] * v.x + a[3] * v.y + a[6] * v.z,
                a[1] * v.x + a[4] * v.y + a[7] * v.z,
                a[2] * v.x + a[5] * v.y + a[8] * v.z);
    }

    /**
     * A bound on the coordinates of A·p + b for any p whose coordinates are at most {@code s} in
     * magnitude: ‖A‖∞·s + max|b_i|. The rounding error of mapping a point grows with it.
     */
    public double pointScale(double s) {
        double rows = 0;
        for (int r = 0; r < 3; r++) {
            rows = Math.max(rows, Math.abs(a[3 * r]) + Math.abs(a[3 * r + 1]) + Math.abs(a[3 * r + 2]));
        }
        return rows * s + b.maxAbs();
    }

    public double determinant() {
        return a[0] * (a[4] * a[8] - a[5] * a[7])
                - a[1] * (a[3] * a[8] - a[5] * a[6])
                + a[2] * (a[3] * a[7] - a[4] * a[6]);
    }

    /** The inverse map, by the adjugate; throws for a singular map (e.g. a zero scale). */
    public Affine inverse() {
        double det = determinant();
        if (det == 0 || !Double.isFinite(det)) {
            throw new IllegalArgumentException("the transform cannot be inverted (its determinant is " + det
                    + "); expected scales and rotations whose product is nonzero and finite");
        }
        double[] m = {
            (a[4] * a[8] - a[5] * a[7]) / det, (a[2] * a[7] - a[1] * a[8]) / det, (a[1] * a[5] - a[2] * a[4]) / det,
            (a[5] * a[6] - a[3] * a[8]) / det, (a[0] * a[8] - a[2] * a[6]) / det, (a[2] * a[3] - a[0] * a[5]) / det,
            (a[3] * a[7] - a[4] * a[6]) / det, (a[1] * a[6] - a[0] * a[7]) / det, (a[0] * a[4] - a[1] * a[3]) / det,
        };
        Affine linearInverse = new Affine(m, Vec3.ZERO);
        return new Affine(m, linearInverse.applyToVector(b).negate());
    }

    /** Whether it only moves points: its linear part is exactly the identity, so shapes keep their form. */
    public boolean isTranslation() {
        for (int k = 0; k < 9; k++) {
            if (a[k] != IDENTITY.a[k]) {
                return false;
            }
        }
        return true;
    }

    /** Exactly the identity (−0.0 counts as 0, as a rotation by 0° produces it). */
    public boolean isIdentity() {
        return isTranslation() && b.x == 0 && b.y == 0 && b.z == 0;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Affine && java.util.Arrays.equals(a, ((Affine) o).a) && b.equals(((Affine) o).b);
    }

    @Override
    public int hashCode() {
        return java.util.Arrays.hashCode(a) * 31 + b.hashCode();
    }

    @Override
    public String toString() {
        return String.format("[%g %g %g | %g; %g %g %g | %g; %g %g %g | %g]",
                a[0], a[1], a[2], b.x, a[3], a[4], a[5], b.y, a[6], a[7], a[8], b.z);
    }
}
