package ray.grading.judge;

import ray.IntersectionRecord;
import ray.Ray;
import ray.surface.Surface;

/**
 * A surface the student's code made and put in a record (say, {@code out.surface = new Sphere()}):
 * the judge knows only its class. It has no shader and is never hit; a test that expects a surface
 * of its own sees another object, as it would have.
 */
final class ForeignSurface extends Surface {
    private final String className;

    ForeignSurface(String className) {
        this.className = className;
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        return false;
    }

    @Override
    public String toString() {
        return "a " + className.substring(className.lastIndexOf('.') + 1) + " your code made";
    }
}
