package ray;

import java.util.function.Supplier;

/**
 * Answers that may come late. In your own runs this class does nothing: every method of yours
 * answers when it is called. When the course grades your code, the tests run in one process and
 * your classes in another, and asking the other process one question at a time would make a render
 * take minutes. So a computation that asks many questions (a pixel of a render, a test's loop of
 * thousands of rays) runs in rounds: an answer not yet known is guessed and noted, the questions
 * noted are asked together, and the computation runs again, until it runs on known answers alone.
 * Only that last run counts, so the result is the one a single process would have computed.
 *
 * <p>The grading process installs its rounds ({@link #install}); the renderer marks each pixel as a
 * computation ({@link #begin}, {@link #end}), and a test wraps a loop in {@link #exactly}.
 */
public abstract class AnswerRounds {
    /** More rounds than any honest computation needs: each round answers at least one more question. */
    public static final int MAX_ROUNDS = 200;

    private static volatile AnswerRounds installed;

    /** Installs the grading process's rounds; from then on answers may come late. */
    public static void install(AnswerRounds rounds) {
        installed = rounds;
    }

    /** Whether answers may come late (only while grading). */
    public static boolean active() {
        return installed != null;
    }

    /**
     * Starts a computation on this thread: from now until {@link #end}, an unknown answer is guessed.
     * {@code state} is what {@link #end} returned when this computation last ran (null the first time):
     * what it asked and was told, so that it need not ask again.
     */
    public static void begin(Object state) {
        AnswerRounds r = installed;
        if (r != null) {
            r.beginComputation(state);
        }
    }

    /**
     * Ends this thread's computation: null when it used no guess, so that its result stands; else its
     * state, for {@link #begin} when it runs again after the next {@link #fetch}.
     */
    public static Object end() {
        AnswerRounds r = installed;
        return r == null ? null : r.endComputation();
    }

    /** Asks every question guessed since the last call, together; false when none was. */
    public static boolean fetch() {
        Object asked = ask();
        if (asked == null) {
            return false;
        }
        await(asked);
        return true;
    }

    /**
     * Asks every question guessed since the last call, without waiting for the answers, so that this
     * process can go on with other computations meanwhile; null when none was guessed. The answers are
     * in once {@link #await} returns.
     */
    public static Object ask() {
        AnswerRounds r = installed;
        return r == null ? null : r.askGuessed();
    }

    /** Waits until the answers to what {@link #ask} asked are in (and those to everything asked before it). */
    public static void await(Object asked) {
        AnswerRounds r = installed;
        if (r != null && asked != null) {
            r.awaitAnswers(asked);
        }
    }

    /** Forgets what the computations asked and learned: the objects asked about may change from here on. */
    public static void forget() {
        AnswerRounds r = installed;
        if (r != null) {
            r.forgetAnswers();
        }
    }

    /**
     * The copy of a surface made of parts (a set of triangles, a placement) that a render searches
     * ({@code copy}, made by {@code original}'s searchCopy, with {@code accelerated} telling whether it
     * searches by its tree): itself, unless the rounds search it as a whole where its parts' classes
     * run (one question a ray, not one a part the search visits).
     */
    public static ray.surface.Surface searched(ray.surface.Surface original, boolean accelerated, ray.surface.Surface copy) {
        AnswerRounds r = installed;
        return r == null ? copy : r.searchedAsWhole(original, accelerated, copy);
    }

    /**
     * The result of {@code computation}, run in rounds until it used no guess (once, when answers
     * never come late). It may run several times, so it must only compute: no output, nothing kept
     * between runs. What it throws counts only from a run that used no guess.
     */
    public static <T> T exactly(Supplier<T> computation) {
        if (!active()) {
            return computation.get();
        }
        try {
            Object state = null;
            for (int round = 1; ; round++) {
                begin(state);
                T result = null;
                RuntimeException failure = null;
                Error error = null;
                try {
                    result = computation.get();
                } catch (RuntimeException e) {
                    failure = e;
                } catch (Error e) {
                    error = e;
                }
                state = end();
                if (state == null) {
                    if (error != null) {
                        throw error;
                    }
                    if (failure != null) {
                        throw failure;
                    }
                    return result;
                }
                if (!fetch() || round >= MAX_ROUNDS) {
                    throw new IllegalStateException("the answers of the code under test never settled after " + round
                            + " rounds: does it answer the same question differently each time?");
                }
            }
        } finally {
            forget();
        }
    }

    protected abstract void beginComputation(Object state);

    protected abstract Object endComputation();

    protected abstract Object askGuessed();

    protected abstract void awaitAnswers(Object asked);

    protected abstract void forgetAnswers();

    protected ray.surface.Surface searchedAsWhole(ray.surface.Surface original, boolean accelerated, ray.surface.Surface copy) {
        return copy;
    }
}
