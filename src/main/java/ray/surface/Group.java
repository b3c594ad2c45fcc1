package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;

/** A list of surfaces (GroupSurface's {@code surfaces}, in the scene's order), hit by the closest of them. */
public class Group extends GroupSurface {
    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        // TODO(Task 4): find the closest hit among this group's surfaces.
        //   Return whether any of this group's surfaces is hit, with out holding the closest hit; on a miss
        //   leave out exactly as it was.
        //   Conventions (the reference images depend on them):
        //   - The hit counts only within the ray's segment (ray.start < t < ray.end).
        //   - Surfaces are tested in order and a tie keeps the earlier surface; a surface fills a record
        //     only when it is hit.
        // HINTS steps
        //   1) Test the surfaces in order against a copy of the ray, which you may shorten.
        //   2) After each hit, make the copy end at that hit, so that only closer hits count from then on.
        //   3) Return whether anything was hit, with out holding the closest hit (copy it over if you
        //      tested into a record of your own).
        // HINTS formulas
        //   1) Test the surfaces in order against a copy of the ray (ray.copy()), which you may shorten.
        //   2) After each hit, shorten the copy to end at that hit's t, so that only closer hits count
        //      from then on (and a tie keeps the earlier surface).
        //   3) Return whether any surface was hit, with out holding the closest hit. Each surface
        //      fills out only when it is hit; if you test into a record of your own, copy every
        //      field of the closest hit into out (out.set(record) does).
        // END HINTS
        // BEGIN SOLUTION
        Ray closestSoFar = ray.copy();
        boolean hitAny = false;
        for (Surface surface : surfaces) {
            if (surface.intersect(out, closestSoFar)) {
                closestSoFar.end = out.t;
                hitAny = true;
            }
        }
        return hitAny;
        // END SOLUTION
        // STUB: return false;
    }
}
