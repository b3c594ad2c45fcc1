package ray.grading.worker;

import java.util.List;
import ray.surface.Triangle;
import ray.surface.TriangleSet;

/**
 * A set of the student's triangles (a mesh's, a box's), built here from their twins in the judge's
 * order, so that the framework builds the same tree over them and searches it as the judge's copy
 * would: one question a ray instead of one a triangle the tree visits.
 */
final class MirroredTriangles extends TriangleSet {
    MirroredTriangles(List<Triangle> triangles) {
        setTriangles(triangles);
    }
}
