package ray.surface;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.function.UnaryOperator;
import ray.Ray;
import ray.accel.Acceleration;
import ray.accel.SearchCounter;
import ray.math.Bounds;
import ray.math.Vec3;

/**
 * A group's data and everything about it but the closest-hit search, which the student's
 * {@link Group} adds: its surfaces in the scene's order, and the copies the framework makes of it
 * (moved to the camera's frame, counted for a renderer thread). A copy is a new group of the same
 * class, made by its no-argument constructor, so it searches with the student's loop and starts
 * from none of the original's state (a list the student's loop might have cached).
 */
public abstract class GroupShape extends Surface {
    /** The group's surfaces in the scene's order. */
    protected final List<Surface> surfaces = new ArrayList<>();

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
        GroupShape copy = copyOver(part -> part.inFrameAt(origin));
        return copy != null ? copy : super.inFrameAt(origin);
    }

    /** The same group over the parts' counted copies: the student's loop still finds the closest hit. */
    @Override
    public Surface searchCopy(Acceleration acceleration, SearchCounter counter) {
        GroupShape copy = copyOver(part -> part.searchCopy(acceleration, counter));
        return copy != null ? copy : super.searchCopy(acceleration, counter);
    }

    /**
     * A new group of this class with this group's shader, holding {@code copyPart} of each part in
     * order; or null when the class cannot be made that way (no public no-argument constructor: an
     * anonymous subclass in a test), whose copies are then made as any other surface's.
     */
    private GroupShape copyOver(UnaryOperator<Surface> copyPart) {
        GroupShape copy;
        try {
            copy = getClass().getConstructor().newInstance();
        } catch (ReflectiveOperationException | RuntimeException e) {
            return null;
        }
        copy.setShader(getShader());
        for (Surface part : surfaces) {
            copy.addSurface(copyPart.apply(part));
        }
        return copy;
    }

    @Override
    public String toString() {
        return super.toString() + "[" + surfaces.size() + " surfaces]";
    }
}
