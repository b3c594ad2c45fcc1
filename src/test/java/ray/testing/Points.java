package ray.testing;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Marks a test as graded: it is worth {@code value} points toward its task, the task whose test
 * classes the table of tasks says it is one of ({@link StudentTask#ofTestClass}). On a class, it
 * applies to every test method of the class that has no {@code @Points} of its own.
 *
 * <p>Tests under src/test/java ship to students and must be {@link Visibility#VISIBLE}; hidden
 * tests live under src/instructorTest/java and never leave the instructor's tree.
 *
 * <p>A {@link #bonus()} test is extra credit: it adds {@code value} points when it passes and costs
 * nothing when it fails.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target({ElementType.TYPE, ElementType.METHOD})
public @interface Points {
    double value();

    Visibility visibility() default Visibility.VISIBLE;

    /**
     * Extra credit, within a required task (every test of an extra-credit task is extra credit
     * anyway): the test is worth {@code value} points on top of the maximum when it passes and
     * nothing when it fails. In Gradescope's results.json its entry has {@code max_score} =
     * {@code value} and {@code score} = {@code value} when passed, and the total's maximum leaves it
     * out; Gradescope shows a score above the maximum as extra credit. Its failure message names the task with ", bonus" (see {@link StudentTaskRule}).
     */
    boolean bonus() default false;
}
