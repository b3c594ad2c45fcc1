package ray.surface;

import java.util.ArrayList;
import java.util.List;

/**
 * A group's data, for the student's {@link Group}, which adds the closest-hit search: its surfaces
 * in the scene's order. (What the framework knows of a group besides, its copies included, is in
 * {@link GroupFacts}.)
 */
public abstract class GroupSurface extends Surface {
    /** The group's surfaces in the scene's order. */
    protected final List<Surface> surfaces = new ArrayList<>();

    public void addSurface(Surface surface) {
        surfaces.add(surface);
    }
}
