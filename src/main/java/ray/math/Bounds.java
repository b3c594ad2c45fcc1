package ray.math;

/**
 * An axis-aligned bounding box, the cheap test a renderer makes before the exact ones: a ray that
 * misses a surface's box cannot hit the surface. {@link #EVERYTHING} stands for a surface whose
 * extent is unknown (never skipped), {@link #EMPTY} for one with no parts (always skipped).
 *
 * <p>The test must never skip a hit that the exact test would report, even one rounded to just
 * outside the box (a triangle lying in the box's face, a grazing ray). So {@link #mayHit} widens
 * the box by {@link #PAD} of its coordinates' magnitude and the ray's interval by the same share
 * of its ends, far more than the rounding of a hit point or of a slab's t (a few ulps; pbrt widens
 * by 2γ₃, Pharr et al. §6.8.2) and far less than makes a difference to what is skipped.
 */
public final class Bounds {
    /** The relative widening of boxes and t intervals, 2⁻³⁰ (about 1e-9). */
    public static final double PAD = 0x1p-30;
    public static final Bounds EMPTY = new Bounds(
            Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY);
    public static final Bounds EVERYTHING = new Bounds(
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY,
            Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY);

    public final double minX, minY, minZ;
    public final double maxX, maxY, maxZ;

    public Bounds(double minX, double minY, double minZ, double maxX, double maxY, double maxZ) {
        this.minX = minX;
        this.minY = minY;
        this.minZ = minZ;
        this.maxX = maxX;
        this.maxY = maxY;
        this.maxZ = maxZ;
    }

    /** The box of the given points; NaN coordinates make it {@link #EVERYTHING}. */
    public static Bounds of(Vec3... points) {
        Bounds b = EMPTY;
        for (Vec3 p : points) {
            b = b.union(new Bounds(p.x, p.y, p.z, p.x, p.y, p.z));
        }
        return b;
    }

    /** The cube of half-side r about c (a sphere's box). */
    public static Bounds around(Vec3 c, double r) {
        double h = Math.abs(r);
        return new Bounds(c.x - h, c.y - h, c.z - h, c.x + h, c.y + h, c.z + h);
    }

    public Bounds union(Bounds o) {
        if (isNaN() || o.isNaN()) {
            return EVERYTHING;
        }
        return new Bounds(Math.min(minX, o.minX), Math.min(minY, o.minY), Math.min(minZ, o.minZ),
                Math.max(maxX, o.maxX), Math.max(maxY, o.maxY), Math.max(maxZ, o.maxZ));
    }

    public boolean isEmpty() {
        return !(minX <= maxX && minY <= maxY && minZ <= maxZ) && !isNaN();
    }

    /** Whether every coordinate is finite (so that the box can be mapped by a transform). */
    public boolean isFinite() {
        return Double.isFinite(minX) && Double.isFinite(minY) && Double.isFinite(minZ)
                && Double.isFinite(maxX) && Double.isFinite(maxY) && Double.isFinite(maxZ);
    }

    private boolean isNaN() {
        return Double.isNaN(minX) || Double.isNaN(minY) || Double.isNaN(minZ)
                || Double.isNaN(maxX) || Double.isNaN(maxY) || Double.isNaN(maxZ);
    }

    /** The box of this box's eight corners mapped by m: it holds everything this box holds, mapped. */
    public Bounds transformed(Affine m) {
        if (isEmpty() || m.isIdentity()) {
            return this;
        }
        if (!isFinite()) {
            return EVERYTHING;
        }
        Bounds b = EMPTY;
        for (int k = 0; k < 8; k++) {
            Vec3 corner = new Vec3((k & 1) == 0 ? minX : maxX, (k & 2) == 0 ? minY : maxY, (k & 4) == 0 ? minZ : maxZ);
            b = b.union(of(m.applyToPoint(corner)));
        }
        return b;
    }

    /**
     * Whether the ray may hit something inside this box for some t in (ray.start, ray.end): false
     * only when it certainly cannot, even allowing for rounding (see the class comment). Slabs: on
     * each axis the ray is between the box's planes for t in [(min − o)/d, (max − o)/d] (swapped when
     * d &lt; 0), and the box is hit where the three intervals and the ray's overlap. A NaN from a ray
     * starting in a slab's plane parallel to it never rejects.
     */
    public boolean mayHit(Vec3 origin, Vec3 direction, double start, double end) {
        if (isEmpty()) {
            return false;
        }
        double padX = pad(minX, maxX);
        double padY = pad(minY, maxY);
        double padZ = pad(minZ, maxZ);
        return slabsOverlap(minX - padX, minY - padY, minZ - padZ, maxX + padX, maxY + padY, maxZ + padZ,
                origin.x, origin.y, origin.z, 1 / direction.x, 1 / direction.y, 1 / direction.z,
                widenedStart(start), widenedEnd(end));
    }

    /** How far a box's side from {@code min} to {@code max} on one axis is widened: {@link #PAD} of its magnitude. */
    public static double pad(double min, double max) {
        return PAD * Math.max(Math.abs(min), Math.abs(max));
    }

    /** The ray's start widened by {@link #PAD} of its magnitude. */
    public static double widenedStart(double start) {
        return start - PAD * Math.abs(start);
    }

    /** The ray's end widened by {@link #PAD} of its magnitude. */
    public static double widenedEnd(double end) {
        return end + PAD * Math.abs(end);
    }

    /**
     * The slab test on a box that is already padded, for a ray interval [near, far] already widened
     * ({@link #widenedStart}, {@link #widenedEnd}): a BVH pads its nodes once when it is built.
     */
    public static boolean slabsOverlap(double minX, double minY, double minZ, double maxX, double maxY, double maxZ,
            double ox, double oy, double oz, double invX, double invY, double invZ, double near, double far) {
        double t0 = (minX - ox) * invX;
        double t1 = (maxX - ox) * invX;
        // Written so that a NaN (a ray starting in a slab's plane, parallel to it) leaves near and far as they were.
        double lo = Math.min(t0, t1);
        double hi = Math.max(t0, t1);
        near = lo > near ? lo : near;
        far = hi < far ? hi : far;
        t0 = (minY - oy) * invY;
        t1 = (maxY - oy) * invY;
        lo = Math.min(t0, t1);
        hi = Math.max(t0, t1);
        near = lo > near ? lo : near;
        far = hi < far ? hi : far;
        t0 = (minZ - oz) * invZ;
        t1 = (maxZ - oz) * invZ;
        lo = Math.min(t0, t1);
        hi = Math.max(t0, t1);
        near = lo > near ? lo : near;
        far = hi < far ? hi : far;
        return near <= far + PAD * Math.abs(far);
    }

    @Override
    public String toString() {
        return "Bounds[(" + minX + ", " + minY + ", " + minZ + ") to (" + maxX + ", " + maxY + ", " + maxZ + ")]";
    }
}
