package ray.shading;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Marks a scene-file property (a setter the loader binds an element to) that only one course's
 * conventions have, such as 2019's {@code <mirrorCoefficient>}. A scene that uses it under another
 * course is refused, with one line naming every such element, rather than rendered by rules that
 * would silently ignore it.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.METHOD)
public @interface OnlyInCourse {
    /** The course's year: "2019". */
    String value();
}
