package ray.fuzz;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.BiFunction;
import java.util.function.Function;

/**
 * The seeded mutational fuzzer: runs cases 0 … n−1 of a seed over the corpus on a number of
 * workers, each in its own copy of the scenes, and gathers a {@link FuzzSummary}. A case that has
 * not ended after {@link #CASE_SECONDS} is a hang; the worker that ran it stops there (its thread
 * may never return), and the others go on. A runner that throws fails its case only.
 */
final class Fuzzer {
    /** A case renders a 4×4 window in milliseconds; this long means the framework is stuck. */
    static final int CASE_SECONDS = 30;

    private final Corpus corpus;
    private final Path work;
    private final long seed;
    private final int workers;
    /** Where the damaged files of failed cases are kept for replay (null: not kept). */
    private final Path failures;
    /** Makes the runner of one worker from its copy of the corpus. */
    private final Function<Path, BiFunction<FuzzCase, byte[], Outcome>> runners;
    private final int caseSeconds;

    Fuzzer(Corpus corpus, Path work, long seed, int workers, Path failures) {
        this(corpus, work, seed, workers, failures, folder -> new CaseRunner(corpus, folder)::run, CASE_SECONDS);
    }

    /** With another runner and time limit, so that a test can check how hangs and crashes of a case are caught. */
    Fuzzer(Corpus corpus, Path work, long seed, int workers, Path failures,
            Function<Path, BiFunction<FuzzCase, byte[], Outcome>> runners,
            int caseSeconds) {
        this.corpus = corpus;
        this.work = work;
        this.seed = seed;
        this.workers = workers;
        this.failures = failures;
        this.runners = runners;
        this.caseSeconds = caseSeconds;
    }

    FuzzSummary run(long cases) throws InterruptedException {
        FuzzSummary summary = new FuzzSummary(seed, cases, workers);
        long start = System.nanoTime();
        List<Thread> threads = new ArrayList<>();
        for (int w = 0; w < workers; w++) {
            int worker = w;
            Thread t = new Thread(() -> work(worker, cases, summary), "fuzz-" + w);
            t.start();
            threads.add(t);
        }
        for (Thread t : threads) {
            t.join();
        }
        summary.finish(System.nanoTime() - start);
        return summary;
    }

    private void work(int worker, long cases, FuzzSummary summary) {
        Path folder = work.resolve("worker-" + worker);
        corpus.copyTo(folder);
        BiFunction<FuzzCase, byte[], Outcome> runner = runners.apply(folder);
        ExecutorService executor = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "fuzz-case-" + worker);
            t.setDaemon(true);
            return t;
        });
        try {
            for (long i = worker; i < cases; i += workers) {
                FuzzCase c = FuzzCase.of(corpus, seed, i);
                byte[] damaged = CaseRunner.damaged(corpus, c);
                Future<Outcome> future = executor.submit(() -> runner.apply(c, damaged));
                Outcome outcome;
                try {
                    outcome = future.get(caseSeconds, TimeUnit.SECONDS);
                } catch (TimeoutException e) {
                    future.cancel(true);
                    outcome = Outcome.failed("no result after " + caseSeconds + " s (a hang)", TimeUnit.SECONDS.toNanos(caseSeconds));
                    record(summary, c, damaged, outcome);
                    summary.abandoned(worker, i);
                    return;
                } catch (ExecutionException e) {
                    outcome = Outcome.failed("the case runner threw " + CaseRunner.describe(e.getCause()), 0);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
                record(summary, c, damaged, outcome);
            }
        } finally {
            executor.shutdownNow();
        }
    }

    private void record(FuzzSummary summary, FuzzCase c, byte[] damaged, Outcome outcome) {
        summary.add(c, outcome, Arrays.equals(damaged, corpus.original(c.target)));
        if (outcome.kind == Outcome.Kind.FAILED && failures != null) {
            keep(c, damaged);
        }
    }

    /** Writes the damaged file of a failed case under failures/case-N/, at its path in the corpus. */
    private void keep(FuzzCase c, byte[] damaged) {
        try {
            Path copy = failures.resolve("case-" + c.index).resolve(c.target.toString());
            Files.createDirectories(copy.getParent());
            Files.write(copy, damaged);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
