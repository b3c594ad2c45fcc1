package ray.surface;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import ray.Ray;
import ray.accel.Acceleration;
import ray.accel.SearchCounter;
import ray.math.Bounds;
import ray.math.Vec3;

/**
 * A group's data and everything about it but the closest-hit search, which the student's
 * {@link Group} adds: its surfaces in the scene's order, and the copies the framework makes of it
 * (moved to the camera's frame, counted for a renderer thread), which keep the student's class and
 * so the student's loop.
 */
public abstract class GroupShape extends Surface {
    /** The group's surfaces in the scene's order (a copy gets a list of its own). */
    protected List<Surface> surfaces = new ArrayList<>();

    public void addSurface(Surface surface) {
        surfaces.add(surface);
    }

    @Override
    public List<Surface> children() {
        return Collections.unmodifiableList(surfaces);
    }

    /** An empty group holds nothing, so no ray can reach it. */
    @Override
    public Bounds bounds() {
        return surfaces.isEmpty() ? Bounds.EMPTY : super.bounds();
    }

    @Override
    public boolean isPrimitive() {
        return false;
    }

    /** Any hit answers a shadow ray, so the parts are asked in turn until one is hit. */
    @Override
    public boolean intersectsAny(Ray ray) {
        for (int k = 0, n = surfaces.size(); k < n; k++) {
            if (surfaces.get(k).intersectsAny(ray)) {
                return true;
            }
        }
        return false;
    }

    /** The same group with every part moved, so that the student's loop searches the moved parts. */
    @Override
    public Surface inFrameAt(Vec3 origin) {
        List<Surface> moved = new ArrayList<>();
        for (Surface part : surfaces) {
            moved.add(part.inFrameAt(origin));
        }
        return withParts(moved);
    }

    /** The same group over the parts' counted copies: the student's loop still finds the closest hit. */
    @Override
    public Surface searchCopy(Acceleration acceleration, SearchCounter counter) {
        List<Surface> counted = new ArrayList<>();
        for (Surface part : surfaces) {
            counted.add(part.searchCopy(acceleration, counter));
        }
        return withParts(counted);
    }

    private GroupShape withParts(List<Surface> parts) {
        GroupShape copy = (GroupShape) copy();
        copy.surfaces = parts;
        return copy;
    }

    @Override
    public String toString() {
        return super.toString() + "[" + surfaces.size() + " surfaces]";
    }
}
