package ray.grading;

import java.lang.annotation.Annotation;
import java.lang.reflect.Method;
import java.util.List;
import org.junit.runner.Description;

/**
 * A test's {@code @Points}, read by name and by reflection: the test classes may be loaded by
 * another class loader than the grader's (a child JVM's, or a fresh loader per graded variant).
 */
public final class PointsAnnotation {
    private static final String POINTS = "ray.testing.Points";

    private PointsAnnotation() {
    }

    /** The test's @Points (on the method, else on its class), or null for an ungraded test. */
    public static Annotation of(Description d) {
        Annotation found = find(d.getAnnotations());
        if (found == null && d.getTestClass() != null) {
            found = find(List.of(d.getTestClass().getAnnotations()));
        }
        return found;
    }

    /** A test class's @Points: on the class, else on its first test method that has one; null for none. */
    static Annotation ofClass(Class<?> type) {
        Annotation found = find(List.of(type.getAnnotations()));
        for (Method m : type.getMethods()) {
            if (found == null) {
                found = find(List.of(m.getAnnotations()));
            }
        }
        return found;
    }

    /** The value of one of its elements: {@code value}, {@code task}, {@code bonus}, {@code visibility}. */
    public static Object element(Annotation points, String name) {
        try {
            Method m = points.annotationType().getMethod(name);
            return m.invoke(points);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot read @Points." + name, e);
        }
    }

    /** A public field of an enum element (the task's {@code number} or {@code title}, the visibility's {@code gradescope}). */
    public static Object field(Annotation points, String element, String field) {
        Object value = element(points, element);
        try {
            return value.getClass().getField(field).get(value);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot read @Points." + element + "." + field, e);
        }
    }

    private static Annotation find(Iterable<Annotation> annotations) {
        for (Annotation a : annotations) {
            if (a.annotationType().getName().equals(POINTS)) {
                return a;
            }
        }
        return null;
    }
}
