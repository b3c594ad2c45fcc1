package ray.surface;

import ray.IntersectionRecord;
import ray.math.Affine;
import ray.math.Bounds;
import ray.math.Vec3;

/**
 * A capped cylinder's data and everything about it but the ray test, which the student's
 * {@link Cylinder} adds (extra credit): the solid whose bottom cap is the disc of {@code radius}
 * about {@code center} in the plane y = center.y, rising along +y by {@code height}. Any other
 * orientation is a {@code <rotate>} away, as for every surface.
 */
public abstract class CylinderShape extends RoundShape {
    protected double height = 1.0;

    public double getHeight() {
        return height;
    }

    public void setHeight(double height) {
        this.height = positive("height", height);
    }

    /**
     * The hit put back on the part of the surface its normal names: onto the side at distance
     * {@code radius} from the axis, or into a cap's plane, as the sphere's hit is re-projected
     * (Ray Tracing Gems ch. 6), so that new rays start on the surface to the rounding of its own
     * numbers. The scale is that of the numbers the point is computed from: the center, the
     * radius and the height.
     */
    @Override
    public HitGeometry hitGeometry(IntersectionRecord hit) {
        Vec3 p = hit.location;
        Vec3 normal = hit.normal == null ? Vec3.ZERO : hit.normal.normalized();
        double scale = center.maxAbs() + radius + height;
        if (Math.abs(normal.y) > 0.5) {
            double capY = normal.y > 0 ? center.y + height : center.y;
            // In the cap's plane to one rounding of its height; x and z only slide the point within it.
            double rounding = HitGeometry.gamma(1);
            Vec3 error = new Vec3(rounding * Math.abs(p.x), rounding * Math.abs(capY), rounding * Math.abs(p.z));
            return new HitGeometry(p, new Vec3(p.x, capY, p.z), normal, scale, error);
        }
        Vec3 radial = new Vec3(p.x - center.x, 0, p.z - center.z).normalized();
        if (!(radial.lengthSquared() > 0)) {
            // On the axis: no direction to re-project along, so nothing better than the reported point.
            return HitGeometry.atReportedPoint(hit);
        }
        Vec3 point = new Vec3(center.x + radius * radial.x, p.y, center.z + radius * radial.z);
        // As a sphere's, in x and z: |radial| = 1 within γ(5), and one rounding of each coordinate.
        double radialError = HitGeometry.gamma(6) * radius;
        double rounding = HitGeometry.gamma(1);
        Vec3 error = new Vec3(radialError * Math.abs(radial.x) + rounding * Math.abs(point.x), rounding * Math.abs(point.y),
                radialError * Math.abs(radial.z) + rounding * Math.abs(point.z));
        return new HitGeometry(p, point, normal, scale, error);
    }

    /** From the bottom cap's square to the top cap's. */
    @Override
    public Bounds bounds() {
        double r = Math.abs(radius);
        return new Bounds(center.x - r, Math.min(center.y, center.y + height), center.z - r,
                center.x + r, Math.max(center.y, center.y + height), center.z + r);
    }

    @Override
    public String toString() {
        return "Cylinder[center " + center + ", radius " + radius + ", height " + height + "]";
    }

    @Override
    public SurfaceKind kind() {
        return SurfaceKind.CYLINDER;
    }

    /**
     * A cylinder that is only moved stays upright, drawn about the middle of its axis (half the
     * height above {@code center}, which is the bottom cap's); one turned or scaled is drawn as its
     * bounding box.
     */
    @Override
    public void sketch(Sketch sketch, Affine toWorld) {
        if (toWorld.isTranslation()) {
            sketch.cylinder(toWorld.applyToPoint(center.plus(new Vec3(0, height / 2, 0))), radius, height);
        } else {
            super.sketch(sketch, toWorld);
        }
    }
}
