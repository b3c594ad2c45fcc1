package ray.grading.judge;

/**
 * A class the judge loads in place of a student's class: the solution's class, whose student method
 * asks the worker, where the student's class runs ({@link StudentCalls}), while its task is graded.
 * Its additions are this interface's methods (named so that no test or student method can mean them).
 */
public interface StandIn {
    /** This object's bookkeeping. */
    StandInState ray1StandIn();

    /** Whether this object's class is graded now: its calls go to the worker, and the worker holds its twin. */
    boolean ray1Remote();

    /** The student class this stands in for ("ray.surface.Sphere"), which the worker makes the twin of. */
    String ray1StudentClass();
}
