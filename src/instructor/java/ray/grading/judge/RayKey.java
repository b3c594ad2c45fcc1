package ray.grading.judge;

import ray.Ray;

/**
 * A ray as a question names it: its origin, direction and start, by their exact bits. The end is
 * not part of it: a search asks the same ray again and again with shorter ends, and the answers for
 * one ray are kept together ({@link IntersectAnswers}).
 */
final class RayKey {
    final long ox;
    final long oy;
    final long oz;
    final long dx;
    final long dy;
    final long dz;
    final long start;
    private final int hash;

    private RayKey(double ox, double oy, double oz, double dx, double dy, double dz, double start) {
        this.ox = Double.doubleToRawLongBits(ox);
        this.oy = Double.doubleToRawLongBits(oy);
        this.oz = Double.doubleToRawLongBits(oz);
        this.dx = Double.doubleToRawLongBits(dx);
        this.dy = Double.doubleToRawLongBits(dy);
        this.dz = Double.doubleToRawLongBits(dz);
        this.start = Double.doubleToRawLongBits(start);
        long h = this.ox;
        h = h * 31 + this.oy;
        h = h * 31 + this.oz;
        h = h * 31 + this.dx;
        h = h * 31 + this.dy;
        h = h * 31 + this.dz;
        h = h * 31 + this.start;
        this.hash = Long.hashCode(h * 0x9E3779B97F4A7C15L);
    }

    /** The key of {@code ray}, or null when its origin or direction is null (never asked: such a ray is sent as it is). */
    static RayKey of(Ray ray) {
        if (ray.origin == null || ray.direction == null) {
            return null;
        }
        return new RayKey(ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z, ray.start);
    }

    static RayKey of(double ox, double oy, double oz, double dx, double dy, double dz, double start) {
        return new RayKey(ox, oy, oz, dx, dy, dz, start);
    }

    /** The ray with segment (start, {@code end}). */
    Ray ray(double end) {
        return new Ray(new ray.math.Vec3(Double.longBitsToDouble(ox), Double.longBitsToDouble(oy), Double.longBitsToDouble(oz)),
                new ray.math.Vec3(Double.longBitsToDouble(dx), Double.longBitsToDouble(dy), Double.longBitsToDouble(dz)),
                Double.longBitsToDouble(start), end);
    }

    double startValue() {
        return Double.longBitsToDouble(start);
    }

    @Override
    public int hashCode() {
        return hash;
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof RayKey)) {
            return false;
        }
        RayKey k = (RayKey) o;
        return k.hash == hash && k.ox == ox && k.oy == oy && k.oz == oz && k.dx == dx && k.dy == dy && k.dz == dz && k.start == start;
    }
}
