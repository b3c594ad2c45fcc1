package ray.surface;

import ray.IntersectionRecord;
import ray.math.Affine;
import ray.math.Bounds;
import ray.math.Vec3;

/** What the framework knows of a capped cylinder ({@link CylinderSurface}) besides its ray test. */
final class CylinderFacts implements ShapeFacts {
    static final CylinderFacts FACTS = new CylinderFacts();

    private CylinderFacts() {
    }

    /**
     * The hit put back on the part of the surface its normal names: onto the side at distance
     * {@code radius} from the axis, or into a cap's plane, as the sphere's hit is re-projected
     * (Ray Tracing Gems ch. 6), so that new rays start on the surface to the rounding of its own
     * numbers. The scale is that of the numbers the point is computed from: the center, the
     * radius and the height.
     */
    @Override
    public HitGeometry hitGeometry(Surface s, IntersectionRecord hit) {
        CylinderSurface cylinder = (CylinderSurface) s;
        Vec3 center = cylinder.center;
        double radius = cylinder.radius;
        double height = cylinder.height;
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
    public Bounds bounds(Surface s) {
        CylinderSurface c = (CylinderSurface) s;
        double r = Math.abs(c.radius);
        return new Bounds(c.center.x - r, Math.min(c.center.y, c.center.y + c.height), c.center.z - r,
                c.center.x + r, Math.max(c.center.y, c.center.y + c.height), c.center.z + r);
    }

    /** A copy with its center moved into the frame whose origin is {@code origin}. */
    @Override
    public Surface inFrameAt(Surface s, Vec3 origin) {
        CylinderSurface moved = (CylinderSurface) s.shallowCopy();
        moved.center = ((CylinderSurface) s).center.minus(origin);
        return moved;
    }

    @Override
    public String name(Surface s) {
        CylinderSurface c = (CylinderSurface) s;
        return "Cylinder[center " + c.center + ", radius " + c.radius + ", height " + c.height + "]";
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
    public void sketch(Surface s, Sketch sketch, Affine toWorld) {
        CylinderSurface c = (CylinderSurface) s;
        if (toWorld.isTranslation()) {
            sketch.cylinder(toWorld.applyToPoint(c.center.plus(new Vec3(0, c.height / 2, 0))), c.radius, c.height);
        } else {
            ShapeFacts.super.sketch(s, sketch, toWorld);
        }
    }
}
