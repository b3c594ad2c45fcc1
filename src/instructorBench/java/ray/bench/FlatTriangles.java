package ray.bench;

import ray.Ray;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * The flat-array baseline for triangles: nine doubles per triangle and the watertight test of Woop,
 * Benthin and Wald (JCGT 2013) inlined in one loop, with the ray's axis permutation and shear
 * computed once per ray, as data-oriented code would. It leaves out the framework's two exact
 * fallbacks (recomputing an edge function that rounds to zero, the exact parallel test): random
 * rays never reach them, and {@link IntersectionBench} checks that both find the same hits.
 */
final class FlatTriangles {
    /** x0 y0 z0 x1 y1 z1 x2 y2 z2 per triangle. */
    private final double[] vertices;

    FlatTriangles(Surface[] triangles) {
        vertices = new double[9 * triangles.length];
        for (int k = 0; k < triangles.length; k++) {
            Triangle t = (Triangle) triangles[k];
            double[] v = {t.getV0().x, t.getV0().y, t.getV0().z, t.getV1().x, t.getV1().y, t.getV1().z,
                    t.getV2().x, t.getV2().y, t.getV2().z};
            System.arraycopy(v, 0, vertices, 9 * k, 9);
        }
    }

    /** The index of the closest triangle the ray hits in (start, end), or −1; its t goes to {@code tOut[0]}. */
    int closest(Ray ray, double[] tOut) {
        double[] o = {ray.origin.x, ray.origin.y, ray.origin.z};
        double[] d = {ray.direction.x, ray.direction.y, ray.direction.z};
        double ax0 = Math.abs(d[0]), ax1 = Math.abs(d[1]), ax2 = Math.abs(d[2]);
        int kz = ax0 >= ax1 && ax0 >= ax2 ? 0 : ax1 >= ax2 ? 1 : 2;
        int kx = (kz + 1) % 3;
        int ky = (kz + 2) % 3;
        double sz = 1 / d[kz];
        double sx = d[kx] * sz;
        double sy = d[ky] * sz;
        double end = ray.end;
        int found = -1;
        for (int k = 0, base = 0; base < vertices.length; k++, base += 9) {
            double az = vertices[base + kz] - o[kz];
            double ax = vertices[base + kx] - o[kx] - sx * az;
            double ay = vertices[base + ky] - o[ky] - sy * az;
            double bz = vertices[base + 3 + kz] - o[kz];
            double bx = vertices[base + 3 + kx] - o[kx] - sx * bz;
            double by = vertices[base + 3 + ky] - o[ky] - sy * bz;
            double cz = vertices[base + 6 + kz] - o[kz];
            double cx = vertices[base + 6 + kx] - o[kx] - sx * cz;
            double cy = vertices[base + 6 + ky] - o[ky] - sy * cz;
            double u = cx * by - cy * bx;
            double v = ax * cy - ay * cx;
            if ((u < 0 && v > 0) || (u > 0 && v < 0)) {
                continue;
            }
            double w = bx * ay - by * ax;
            if (!((u >= 0 && v >= 0 && w >= 0) || (u <= 0 && v <= 0 && w <= 0))) {
                continue;
            }
            double det = u + v + w;
            if (det == 0) {
                continue;
            }
            double t = (u * (sz * az) + v * (sz * bz) + w * (sz * cz)) / det;
            if (t > ray.start && t < end) {
                end = t;
                found = k;
            }
        }
        tOut[0] = end;
        return found;
    }
}
