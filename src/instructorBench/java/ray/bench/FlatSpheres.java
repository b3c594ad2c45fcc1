package ray.bench;

import ray.Ray;
import ray.surface.Sphere;
import ray.surface.Surface;

/**
 * The baseline a data-oriented renderer would write: spheres as flat arrays of doubles and one
 * closest-hit loop with the intersection inlined, no objects, no virtual calls, no vectors. It
 * uses the framework's sphere math (closest-approach discriminant, stable quadratic) and, like
 * the framework, computes the unit direction once per ray, so that the
 * benchmark compares designs, not formulas; {@link IntersectionBench} checks that both find the
 * same hits.
 */
final class FlatSpheres {
    private final double[] cx;
    private final double[] cy;
    private final double[] cz;
    private final double[] radius;

    FlatSpheres(Surface[] spheres) {
        int n = spheres.length;
        cx = new double[n];
        cy = new double[n];
        cz = new double[n];
        radius = new double[n];
        for (int k = 0; k < n; k++) {
            Sphere s = (Sphere) spheres[k];
            cx[k] = s.getCenter().x;
            cy[k] = s.getCenter().y;
            cz[k] = s.getCenter().z;
            radius[k] = s.getRadius();
        }
    }

    /** The index of the closest sphere the ray hits in (start, end), or −1; its t goes to {@code tOut[0]}. */
    int closest(Ray ray, double[] tOut) {
        double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
        double a = dx * dx + dy * dy + dz * dz;
        double rootA = Math.sqrt(a);
        double inverseLength = 1 / rootA;
        double ux = dx * inverseLength, uy = dy * inverseLength, uz = dz * inverseLength;
        double end = ray.end;
        int found = -1;
        for (int k = 0; k < radius.length; k++) {
            double fx = ray.origin.x - cx[k], fy = ray.origin.y - cy[k], fz = ray.origin.z - cz[k];
            double along = fx * ux + fy * uy + fz * uz;
            double lx = fx - ux * along, ly = fy - uy * along, lz = fz - uz * along;
            double r2 = radius[k] * radius[k];
            double discriminantOverA = r2 - (lx * lx + ly * ly + lz * lz);
            if (!(discriminantOverA >= 0)) {
                continue;
            }
            double halfB = fx * dx + fy * dy + fz * dz;
            double c = fx * fx + fy * fy + fz * fz - r2;
            double q = -(halfB + Math.copySign(rootA * Math.sqrt(discriminantOverA), halfB));
            double t0 = q / a;
            double t1 = q != 0 ? c / q : t0;
            double tNear = Math.min(t0, t1);
            double tFar = Math.max(t0, t1);
            double t = tNear > ray.start && tNear < end ? tNear : tFar > ray.start && tFar < end ? tFar : Double.NaN;
            if (t == t) {
                end = t;
                found = k;
            }
        }
        tOut[0] = end;
        return found;
    }
}
