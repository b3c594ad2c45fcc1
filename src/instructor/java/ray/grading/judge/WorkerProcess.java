package ray.grading.judge;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import ray.grading.wire.Frames;
import ray.grading.wire.Protocol;
import ray.grading.wire.WireError;
import ray.grading.wire.WireOut;
import ray.grading.worker.WorkerMain;

/**
 * One running worker, seen from the judge: its pipe, read by a thread of its own into a queue so
 * that the judge's waits can be interrupted (a test's time limit) and bounded (the grade's deadline),
 * and its standard error, drained and mostly dropped. Whatever goes wrong with it (it ends, answers
 * out of turn or out of format, takes too long) is a {@link WorkerFailure}; the caller then ends it
 * ({@link #end}) and starts another for the next call.
 */
final class WorkerProcess {
    /** What the student's code printed that is kept (the rest is dropped). */
    private static final int KEPT_OUTPUT_BYTES = 64 << 10;
    /** How often a wait for the worker looks whether it still runs. */
    private static final long ALIVE_CHECK_NANOS = TimeUnit.MILLISECONDS.toNanos(200);

    private final Process process;
    private final OutputStream toWorker;
    private final BlockingQueue<Object> fromWorker = new LinkedBlockingQueue<>();
    private final Containment containment;
    private final StringBuilder printed = new StringBuilder();
    /**
     * Writes to the worker, one message after another: a caller never blocks on the pipe (a worker
     * that stopped reading fills it), so that a test's time limit can always end its wait.
     */
    private final ExecutorService writer = Executors.newSingleThreadExecutor(r -> JudgeThreads.daemon(r, "ray1-worker-writer"));

    private WorkerProcess(Process process, Containment containment) {
        this.process = process;
        this.containment = containment;
        this.toWorker = new BufferedOutputStream(process.getOutputStream(), 1 << 16);
        Thread reader = JudgeThreads.daemon(this::readFrames, "ray1-worker-reader");
        reader.start();
        Thread drain = JudgeThreads.daemon(this::drainPrinted, "ray1-worker-printed");
        drain.start();
    }

    /**
     * Starts a worker by {@code command} and waits until it says it is ready, at most until
     * {@code deadline} (System.nanoTime).
     */
    static WorkerProcess start(List<String> command, Containment containment, long deadline) {
        Process process;
        try {
            ProcessBuilder builder = new ProcessBuilder(command);
            containment.environment(builder.environment());
            process = builder.start();
        } catch (IOException e) {
            throw new WorkerFailure("the worker could not start: " + e.getMessage());
        }
        WorkerProcess worker = new WorkerProcess(process, containment);
        try {
            Frames.Frame ready = worker.next(deadline);
            if (ready.type != Protocol.READY || !Protocol.VERSION.equals(ready.reader().str(64))) {
                throw new WorkerFailure("the worker did not start as a worker");
            }
        } catch (WorkerFailure | WireError e) {
            worker.end();
            throw e instanceof WorkerFailure ? (WorkerFailure) e : new WorkerFailure("the worker did not start: " + e.getMessage());
        } catch (InterruptedException e) {
            worker.end();
            Thread.currentThread().interrupt();
            throw new WorkerFailure("interrupted while the worker started");
        }
        return worker;
    }

    private void readFrames() {
        try (InputStream in = new BufferedInputStream(process.getInputStream(), 1 << 16)) {
            while (true) {
                Frames.Frame frame = Frames.read(in);
                if (frame == null) {
                    fromWorker.add(new EOFException("the worker's output ended"));
                    return;
                }
                fromWorker.add(frame);
            }
        } catch (IOException | WireError e) {
            fromWorker.add(e);
        }
    }

    private void drainPrinted() {
        byte[] buffer = new byte[8192];
        try (InputStream err = process.getErrorStream()) {
            for (int n = err.read(buffer); n >= 0; n = err.read(buffer)) {
                synchronized (printed) {
                    if (printed.length() < KEPT_OUTPUT_BYTES) {
                        printed.append(new String(buffer, 0, Math.min(n, KEPT_OUTPUT_BYTES - printed.length()),
                                java.nio.charset.StandardCharsets.UTF_8));
                    }
                }
            }
        } catch (IOException e) {
            // The worker ended.
        }
    }

    /** The start of what the student's code printed. */
    String printed() {
        synchronized (printed) {
            return printed.toString();
        }
    }

    /** Sends {@code message} (which nothing may change from here on) after those sent before, without waiting for the pipe. */
    void send(int type, WireOut message) {
        try {
            writer.execute(() -> {
                try {
                    message.send(toWorker, type);
                } catch (IOException e) {
                    // The worker ended or stopped reading: the wait for its answer says so.
                }
            });
        } catch (RejectedExecutionException e) {
            throw new WorkerFailure(WorkerFailure.Kind.ENDED, "the JVM running your code ended before it answered");
        }
    }

    /**
     * The worker's next message, waiting at most until {@code deadline} (System.nanoTime).
     *
     * @throws WorkerFailure        when the worker ended, sent something unreadable or said nothing in time
     * @throws InterruptedException when the waiting thread is interrupted (a test's time limit)
     */
    Frames.Frame next(long deadline) throws InterruptedException {
        Object next = fromWorker.poll();
        while (next == null) {
            long wait = deadline - System.nanoTime();
            if (wait <= 0) {
                throw new WorkerFailure(WorkerFailure.Kind.TIMED_OUT, "the worker gave no answer in time");
            }
            // In slices: a worker that ended says so even when a process it started keeps its output open.
            next = fromWorker.poll(Math.min(wait, ALIVE_CHECK_NANOS), TimeUnit.NANOSECONDS);
            if (next == null && !process.isAlive()) {
                next = fromWorker.poll(ALIVE_CHECK_NANOS, TimeUnit.NANOSECONDS);
                if (next == null) {
                    throw new WorkerFailure(WorkerFailure.Kind.ENDED, endedWhy());
                }
            }
        }
        if (next instanceof Frames.Frame) {
            Frames.Frame frame = (Frames.Frame) next;
            if (frame.type == Protocol.EXITING) {
                throw new WorkerFailure(WorkerFailure.Kind.EXITED, "the code under test called System.exit, which ended its JVM");
            }
            return frame;
        }
        if (next instanceof WireError) {
            throw new WorkerFailure("the worker answered out of format (" + ((Exception) next).getMessage() + ")");
        }
        throw new WorkerFailure(WorkerFailure.Kind.ENDED, endedWhy());
    }

    private String endedWhy() {
        try {
            if (process.waitFor(2, TimeUnit.SECONDS)) {
                int code = process.exitValue();
                // The worker's own last word, when it gave one (a message it could not read): never the student's output.
                String own = printed().lines().filter(l -> l.startsWith(WorkerMain.LAST_WORD)).findFirst().orElse("");
                return "the JVM running your code ended (exit code " + code + ")" + (code == 1 && printed().contains("OutOfMemoryError")
                        ? ": it ran out of memory" : "") + (own.isEmpty() ? "" : " [" + own + "]");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return "the JVM running your code stopped answering";
    }

    boolean alive() {
        return process.isAlive();
    }

    /** Stops the worker's process at once, from any thread: whoever waits for it learns that it ended. */
    void kill() {
        Containment.kill(process);
    }

    /** Ends the worker and everything it started. */
    void end() {
        // The process first: a write blocked on its full pipe then fails, rather than the close waiting for it.
        containment.end(process);
        writer.shutdownNow();
        // Closed aside: a process the student's code started may have kept the pipe's other end (with its
        // standard input inherited), and then a write, and the close after it, wait for as long as it lives.
        JudgeThreads.daemon(() -> {
            try {
                process.getOutputStream().close();
            } catch (IOException e) {
                // Gone already.
            }
        }, "ray1-worker-close").start();
    }
}
