package ray.surface;

import java.util.Collections;
import java.util.List;
import java.util.function.UnaryOperator;
import ray.Ray;
import ray.accel.Acceleration;
import ray.accel.SearchCounter;
import ray.math.Bounds;
import ray.math.Vec3;

/**
 * What the framework knows of a group ({@link GroupSurface}) besides its closest-hit search: its
 * parts, and the copies the framework makes of it (moved to the camera's frame, counted for a
 * renderer thread). A copy is a new group of the same class, made by its no-argument constructor,
 * so it searches with the student's loop and starts from none of the original's state (a list the
 * student's loop might have cached).
 */
final class GroupFacts implements ShapeFacts {
    static final GroupFacts FACTS = new GroupFacts();

    private GroupFacts() {
    }

    @Override
    public List<Surface> children(Surface s) {
        return Collections.unmodifiableList(((GroupSurface) s).surfaces);
    }

    /** An empty group holds nothing, so no ray can reach it. */
    @Override
    public Bounds bounds(Surface s) {
        return ((GroupSurface) s).surfaces.isEmpty() ? Bounds.EMPTY : ShapeFacts.super.bounds(s);
    }

    @Override
    public boolean isPrimitive(Surface s) {
        return false;
    }

    /** Any hit answers a shadow ray, so the parts are asked in turn until one is hit. */
    @Override
    public boolean intersectsAny(Surface s, Ray ray) {
        List<Surface> surfaces = ((GroupSurface) s).surfaces;
        for (int k = 0, n = surfaces.size(); k < n; k++) {
            if (surfaces.get(k).intersectsAny(ray)) {
                return true;
            }
        }
        return false;
    }

    /** The same group with every part moved, so that the student's loop searches the moved parts. */
    @Override
    public Surface inFrameAt(Surface s, Vec3 origin) {
        GroupSurface copy = copyOver((GroupSurface) s, part -> part.inFrameAt(origin));
        return copy != null ? copy : ShapeFacts.super.inFrameAt(s, origin);
    }

    /** The same group over the parts' counted copies: the student's loop still finds the closest hit. */
    @Override
    public Surface searchCopy(Surface s, Acceleration acceleration, SearchCounter counter) {
        GroupSurface copy = copyOver((GroupSurface) s, part -> part.searchCopy(acceleration, counter));
        return copy != null ? copy : ShapeFacts.super.searchCopy(s, acceleration, counter);
    }

    /**
     * A new group of the group's class with its shader, holding {@code copyPart} of each part in
     * order; or null when the class cannot be made that way (no public no-argument constructor: an
     * anonymous subclass in a test), whose copies are then made as any other surface's.
     */
    private static GroupSurface copyOver(GroupSurface group, UnaryOperator<Surface> copyPart) {
        GroupSurface copy;
        try {
            copy = group.getClass().getConstructor().newInstance();
        } catch (ReflectiveOperationException | RuntimeException e) {
            return null;
        }
        copy.setShader(group.getShader());
        for (Surface part : group.surfaces) {
            copy.addSurface(copyPart.apply(part));
        }
        return copy;
    }

    @Override
    public String name(Surface s) {
        return ShapeFacts.namedClass(s) + "[" + ((GroupSurface) s).surfaces.size() + " surfaces]";
    }
}
