package ray.surface;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;

/**
 * A surface made of triangles that it builds itself ({@link Box}, {@link Mesh}), hit by the
 * closest of them: the framework's own closest-hit loop, so a box or mesh needs the student's
 * {@link Triangle} but not their {@link Group}. Ties keep the earlier triangle, as in a group.
 */
public abstract class TriangleSet extends Surface {
    private final List<Triangle> triangles = new ArrayList<>();

    /** Replaces the triangles (by complete(), once the properties are known). */
    protected void setTriangles(List<Triangle> built) {
        triangles.clear();
        triangles.addAll(built);
    }

    @Override
    public List<Surface> children() {
        return Collections.unmodifiableList(triangles);
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        Ray closestSoFar = ray.copy();
        boolean hitAny = false;
        for (Triangle triangle : triangles) {
            if (triangle.intersect(out, closestSoFar)) {
                closestSoFar.end = out.t;
                hitAny = true;
            }
        }
        return hitAny;
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + "[" + triangles.size() + " triangles]";
    }
}
