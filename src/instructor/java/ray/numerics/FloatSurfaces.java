package ray.numerics;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * The solution's intersection tests carried out in float (24-bit) arithmetic, for the accuracy
 * report's "float vs double" sweep: every input (ray, center, radius, vertices) is rounded to
 * float, every operation is a float operation, and the hit (t, location, normal) is reported
 * rounded to float. Each hit names the original primitive, so its shader shades it and the
 * framework starts new rays from the primitive's own numbers, as it does for any student's code;
 * what float changes is which rays hit and where, and the normal that shading sees.
 *
 * <p>Never ships: it is the Task 2 and Task 3 answers in float.
 */
final class FloatSurfaces {
    private FloatSurfaces() {
    }

    /** A copy of the surface tree whose spheres and triangles intersect in float. */
    static Surface of(Surface root) {
        return TextbookSurfaces.replaceLeaves(root, leaf -> leaf instanceof Sphere ? new FloatSphere((Sphere) leaf)
                : leaf instanceof Triangle ? new FloatTriangle((Triangle) leaf) : leaf);
    }

    static Vec3 rounded(double x, double y, double z) {
        return new Vec3((float) x, (float) y, (float) z);
    }

    /** The robust sphere test (closest-approach discriminant, stable roots, re-projection) in float. */
    static final class FloatSphere extends StandIn {
        private final float cx;
        private final float cy;
        private final float cz;
        private final float r;

        FloatSphere(Sphere sphere) {
            super(sphere);
            Vec3 c = sphere.getCenter();
            cx = (float) c.x;
            cy = (float) c.y;
            cz = (float) c.z;
            r = (float) sphere.getRadius();
        }

        @Override
        protected boolean test(IntersectionRecord out, Ray ray) {
            float dx = (float) ray.direction.x;
            float dy = (float) ray.direction.y;
            float dz = (float) ray.direction.z;
            float fx = (float) ray.origin.x - cx;
            float fy = (float) ray.origin.y - cy;
            float fz = (float) ray.origin.z - cz;
            float a = dx * dx + dy * dy + dz * dz;
            float length = (float) Math.sqrt(a);
            float ux = dx / length;
            float uy = dy / length;
            float uz = dz / length;
            float along = fx * ux + fy * uy + fz * uz;
            float lx = fx - along * ux;
            float ly = fy - along * uy;
            float lz = fz - along * uz;
            float discriminantOverA = r * r - (lx * lx + ly * ly + lz * lz);
            if (!(discriminantOverA >= 0) || !(a > 0) || Float.isInfinite(a)) {
                return false;
            }
            float halfB = fx * dx + fy * dy + fz * dz;
            float c = fx * fx + fy * fy + fz * fz - r * r;
            float rootDelta = length * (float) Math.sqrt(discriminantOverA);
            float q = -(halfB + Math.copySign(rootDelta, halfB));
            float t0 = q / a;
            float t1 = q != 0 ? c / q : t0;
            float tNear = Math.min(t0, t1);
            float tFar = Math.max(t0, t1);
            float t;
            if (tNear > ray.start && tNear < ray.end) {
                t = tNear;
            } else if (tFar > ray.start && tFar < ray.end) {
                t = tFar;
            } else {
                return false;
            }
            float px = (float) ray.origin.x + t * dx - cx;
            float py = (float) ray.origin.y + t * dy - cy;
            float pz = (float) ray.origin.z + t * dz - cz;
            float norm = (float) Math.sqrt(px * px + py * py + pz * pz);
            float nx = px / norm;
            float ny = py / norm;
            float nz = pz / norm;
            out.t = t;
            out.location = rounded(cx + r * nx, cy + r * ny, cz + r * nz);
            out.normal = rounded(nx, ny, nz);
            StandInTexCoords.sphere(out, out.normal);
            return true;
        }
    }

    /** The watertight triangle test (Woop, Benthin and Wald 2013) in float, without the double fallback for zero edge functions. */
    static final class FloatTriangle extends StandIn {
        private final Triangle triangle;
        private final float x0, y0, z0, x1, y1, z1, x2, y2, z2;

        FloatTriangle(Triangle triangle) {
            super(triangle);
            this.triangle = triangle;
            x0 = (float) triangle.getV0().x;
            y0 = (float) triangle.getV0().y;
            z0 = (float) triangle.getV0().z;
            x1 = (float) triangle.getV1().x;
            y1 = (float) triangle.getV1().y;
            z1 = (float) triangle.getV1().z;
            x2 = (float) triangle.getV2().x;
            y2 = (float) triangle.getV2().y;
            z2 = (float) triangle.getV2().z;
        }

        @Override
        protected boolean test(IntersectionRecord out, Ray ray) {
            float dx = (float) ray.direction.x, dy = (float) ray.direction.y, dz = (float) ray.direction.z;
            float px = (float) ray.origin.x, py = (float) ray.origin.y, pz = (float) ray.origin.z;
            float a0 = x0 - px, a1 = y0 - py, a2 = z0 - pz;
            float b0 = x1 - px, b1 = y1 - py, b2 = z1 - pz;
            float c0 = x2 - px, c1 = y2 - py, c2 = z2 - pz;
            // The same cyclic renaming of the axes as the double test: the largest |d| component becomes z.
            double ux = Math.abs(ray.direction.x), uy = Math.abs(ray.direction.y), uz = Math.abs(ray.direction.z);
            int kz = ux >= uy && ux >= uz ? 0 : uy >= uz ? 1 : 2;
            float ax, ay, az, bx, by, bz, cx, cy, cz, ex, ey, ez;
            if (kz == 2) {
                ax = a0; ay = a1; az = a2; bx = b0; by = b1; bz = b2; cx = c0; cy = c1; cz = c2; ex = dx; ey = dy; ez = dz;
            } else if (kz == 0) {
                ax = a1; ay = a2; az = a0; bx = b1; by = b2; bz = b0; cx = c1; cy = c2; cz = c0; ex = dy; ey = dz; ez = dx;
            } else {
                ax = a2; ay = a0; az = a1; bx = b2; by = b0; bz = b1; cx = c2; cy = c0; cz = c1; ex = dz; ey = dx; ez = dy;
            }
            float sz = 1 / ez;
            float sx = ex * sz;
            float sy = ey * sz;
            ax -= sx * az;
            ay -= sy * az;
            bx -= sx * bz;
            by -= sy * bz;
            cx -= sx * cz;
            cy -= sy * cz;
            float u = cx * by - cy * bx;
            float v = ax * cy - ay * cx;
            float w = bx * ay - by * ax;
            if (!((u >= 0 && v >= 0 && w >= 0) || (u <= 0 && v <= 0 && w <= 0))) {
                return false;
            }
            float det = u + v + w;
            if (det == 0) {
                return false;
            }
            float t = (u * (sz * az) + v * (sz * bz) + w * (sz * cz)) / det;
            if (!(t > ray.start && t < ray.end)) {
                return false;
            }
            float beta = v / det;
            float gamma = w / det;
            Vec3 n = triangle.normalAt(beta, gamma);
            out.t = t;
            out.location = rounded(px + t * dx, py + t * dy, pz + t * dz);
            out.normal = rounded(n.x, n.y, n.z);
            out.beta = beta;
            out.gamma = gamma;
            StandInTexCoords.triangle(out, triangle, beta, gamma);
            return true;
        }
    }
}
