package ray.grading.judge;

/**
 * What the judge keeps of one stand-in: the handle of its twin in the running worker (and which
 * worker that is), the framework state the twin last got, and whether complete() was called on the
 * stand-in since (the twin then runs its own complete(), the student's if the class has one).
 */
public final class StandInState {
    final Object owner;
    /** The worker the twin lives in ({@link Worker#generation}); another worker has no twin yet. */
    int generation = -1;
    int handle;
    /** The framework state as last sent, to send it again only when it changed. */
    byte[] sentState;
    /** complete() was called since the twin last ran it. */
    boolean completePending;
    /** complete() was ever called on this object (or on the one it was cloned from). */
    boolean completed;

    public StandInState(Object owner) {
        this.owner = owner;
    }

    /** The stand-in this is the bookkeeping of. */
    public Object owner() {
        return owner;
    }

    /** The bookkeeping of a clone of this object: a twin of its own, completed as this one was. */
    public StandInState forClone(Object clone) {
        StandInState copy = new StandInState(clone);
        copy.completed = completed;
        copy.completePending = completed;
        return copy;
    }

    /** complete() ran on the stand-in. */
    public void completed() {
        completed = true;
        completePending = true;
    }
}
