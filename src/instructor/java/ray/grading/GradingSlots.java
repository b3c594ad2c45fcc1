package ray.grading;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The gradings that run at once (gradeAll, the diagnosis evaluation), each in a slot: slot k's
 * student code runs as a user of its own ({@link Sandbox#userOf}), so that no submission can reach
 * another's processes or folders, and ending one grading's processes ends none of another's. A pool's
 * thread keeps its slot for every grading it runs.
 */
final class GradingSlots {
    private static final ThreadLocal<Integer> SLOT = ThreadLocal.withInitial(() -> 0);

    private GradingSlots() {
    }

    /** A pool of {@code jobs} threads, the k-th of which grades in slot k. */
    static ExecutorService pool(int jobs) {
        AtomicInteger next = new AtomicInteger();
        return Executors.newFixedThreadPool(jobs, runnable -> {
            int slot = next.getAndIncrement();
            Thread thread = new Thread(() -> {
                SLOT.set(slot);
                runnable.run();
            }, "grading-slot-" + slot);
            thread.setDaemon(true);
            return thread;
        });
    }

    /** This thread's slot (0 outside a pool). */
    static int current() {
        return SLOT.get();
    }
}
