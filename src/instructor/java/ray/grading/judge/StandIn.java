package ray.grading.judge;

/**
 * A class the judge loads in place of a student's class: the same name, superclass and constructors,
 * whose student methods ask the worker, where the student's class runs ({@link StudentCalls}). Its
 * one addition is this interface's method, which gives the judge the object's bookkeeping.
 */
public interface StandIn {
    /** This object's bookkeeping (named so that no test or student method can mean it). */
    StandInState ray1StandIn();
}
