package ray.inspect;

import java.nio.file.Path;
import ray.math.Vec3;
import ray.surface.Box;
import ray.surface.Group;
import ray.surface.Mesh;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * Short names of surfaces, with the numbers that tell them apart (center, vertices, bounds, file),
 * as the trace and the explore page show them.
 */
public final class SurfaceNames {
    public String of(Surface s) {
        if (s instanceof Sphere) {
            Sphere sphere = (Sphere) s;
            return "Sphere center " + Fmt.vec(sphere.getCenter()) + ", radius " + Fmt.num(sphere.getRadius());
        }
        if (s instanceof Triangle) {
            Triangle t = (Triangle) s;
            return "Triangle " + Fmt.vec(t.getV0()) + ", " + Fmt.vec(t.getV1()) + ", " + Fmt.vec(t.getV2());
        }
        if (s instanceof Mesh) {
            Path file = ((Mesh) s).getData() == null ? null : ((Mesh) s).getData().source;
            return "Mesh " + (file != null ? shortPath(file) + " " : "") + "(" + count(s.children().size(), "triangle") + ")";
        }
        if (s instanceof Box) {
            return "Box " + Fmt.vec(((Box) s).getMinPt()) + " to " + Fmt.vec(((Box) s).getMaxPt());
        }
        if (s instanceof Group) {
            return "Group (" + count(s.children().size(), "surface") + ")";
        }
        return s.toString();
    }

    /** "triangle #8", and for a box's triangle the face it belongs to: "triangle #8 (+y face)". */
    static String triangle(Surface shape, Surface triangle, int index) {
        String name = "triangle #" + (index + 1);
        if (!(shape instanceof Box) || !(triangle instanceof Triangle) || ((Triangle) triangle).getFaceNormal() == null) {
            return name;
        }
        Vec3 n = ((Triangle) triangle).getFaceNormal();
        int axis = Math.abs(n.x) >= Math.abs(n.y) && Math.abs(n.x) >= Math.abs(n.z) ? 0 : Math.abs(n.y) >= Math.abs(n.z) ? 1 : 2;
        return name + " (" + (n.get(axis) > 0 ? "+" : "−") + "xyz".charAt(axis) + " face)";
    }

    /** "12 triangles", "1 surface". */
    static String count(int n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }

    /** The path relative to the working folder when the file is under it (as the student wrote it), else as is. */
    public static String shortPath(Path file) {
        Path here = Path.of("").toAbsolutePath();
        Path absolute = file.toAbsolutePath().normalize();
        return (absolute.startsWith(here) ? here.relativize(absolute) : absolute).toString().replace('\\', '/');
    }
}
