package ray.grading.judge;

/**
 * The judge's own background threads (reading a worker's answers and its printing, writing it
 * batches) live in a thread group of their own, apart from the test that first needed them: JUnit
 * looks for a timed-out test's stuck threads in the test's group, and would report these, which
 * serve every later test too, as the test's.
 */
final class JudgeThreads {
    private static final ThreadGroup GROUP = new ThreadGroup(topGroup(), "ray1-judge");

    private JudgeThreads() {
    }

    /** A daemon thread of the judge's group, not started. */
    static Thread daemon(Runnable work, String name) {
        Thread thread = new Thread(GROUP, work, name);
        thread.setDaemon(true);
        return thread;
    }

    private static ThreadGroup topGroup() {
        ThreadGroup group = Thread.currentThread().getThreadGroup();
        while (group.getParent() != null) {
            group = group.getParent();
        }
        return group;
    }
}
