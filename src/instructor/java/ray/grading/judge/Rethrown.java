package ray.grading.judge;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import ray.grading.wire.ThrownData;

/**
 * What the student's code threw in the worker, thrown again in the judge as the tests would have met
 * it in one process: the same type when it is one of the JDK's common throwables (any other is a
 * {@link ForeignThrowable} that names its class), the same message, and a stack trace that is the
 * student's frames from the worker followed by the judge's frames below the stand-in's method, so
 * that a test's message names the student's file and line. No class of the student's is loaded.
 */
final class Rethrown {
    private static final Map<String, Function<String, Throwable>> KNOWN = Map.ofEntries(
            Map.entry("java.lang.ArithmeticException", ArithmeticException::new),
            Map.entry("java.lang.ArrayIndexOutOfBoundsException", ArrayIndexOutOfBoundsException::new),
            Map.entry("java.lang.ArrayStoreException", ArrayStoreException::new),
            Map.entry("java.lang.ClassCastException", ClassCastException::new),
            Map.entry("java.lang.IllegalArgumentException", IllegalArgumentException::new),
            Map.entry("java.lang.IllegalStateException", IllegalStateException::new),
            Map.entry("java.lang.IndexOutOfBoundsException", IndexOutOfBoundsException::new),
            Map.entry("java.lang.NegativeArraySizeException", NegativeArraySizeException::new),
            Map.entry("java.lang.NullPointerException", NullPointerException::new),
            Map.entry("java.lang.NumberFormatException", NumberFormatException::new),
            Map.entry("java.lang.StringIndexOutOfBoundsException", StringIndexOutOfBoundsException::new),
            Map.entry("java.lang.UnsupportedOperationException", UnsupportedOperationException::new),
            Map.entry("java.lang.RuntimeException", RuntimeException::new),
            Map.entry("java.lang.Exception", Exception::new),
            Map.entry("java.lang.Error", Error::new),
            Map.entry("java.lang.AssertionError", m -> m == null ? new AssertionError() : new AssertionError((Object) m)),
            Map.entry("java.lang.StackOverflowError", StackOverflowError::new),
            Map.entry("java.lang.OutOfMemoryError", OutOfMemoryError::new),
            Map.entry("java.lang.NoClassDefFoundError", NoClassDefFoundError::new),
            Map.entry("java.lang.LinkageError", LinkageError::new),
            Map.entry("java.lang.InternalError", InternalError::new),
            Map.entry("java.util.ConcurrentModificationException", java.util.ConcurrentModificationException::new),
            Map.entry("java.util.NoSuchElementException", java.util.NoSuchElementException::new));

    private Rethrown() {
    }

    /**
     * The throwable to throw in the judge for {@code thrown}, raised in a call of a stand-in of class
     * {@code standIn}: the worker's frames, then this thread's frames below that stand-in's method.
     */
    static Throwable of(ThrownData thrown, Class<?> standIn) {
        List<StackTraceElement> below = new ArrayList<>();
        StackTraceElement[] here = new Throwable().getStackTrace();
        int k = 0;
        // Skip the judge's own frames and the stand-in's method: the worker's frames end with the student's.
        while (k < here.length && !here[k].getClassName().equals(standIn.getName())) {
            k++;
        }
        for (k++; k < here.length; k++) {
            below.add(here[k]);
        }
        return build(thrown, below);
    }

    private static Throwable build(ThrownData thrown, List<StackTraceElement> below) {
        Throwable cause = thrown.cause == null ? null : build(thrown.cause, List.of());
        Throwable t;
        if (thrown.className.equals("java.lang.ExceptionInInitializerError") && cause != null) {
            t = new ExceptionInInitializerError(cause);
            cause = null;
        } else {
            Function<String, Throwable> make = KNOWN.get(thrown.className);
            t = make != null ? make.apply(thrown.message) : new ForeignThrowable(thrown.className, thrown.message);
        }
        if (cause != null) {
            try {
                t.initCause(cause);
            } catch (IllegalStateException e) {
                // A constructor that set its own cause keeps it.
            }
        }
        List<StackTraceElement> frames = new ArrayList<>(thrown.frames);
        frames.addAll(below);
        t.setStackTrace(frames.toArray(new StackTraceElement[0]));
        return t;
    }

    /** Throws {@code t}, checked or not, from a method that declares none. */
    @SuppressWarnings("unchecked")
    static <T extends Throwable> RuntimeException sneaky(Throwable t) throws T {
        throw (T) t;
    }

    /** A throwable of a class the judge does not load (the student's own, or a rare JDK one), named as the original. */
    static final class ForeignThrowable extends RuntimeException {
        private static final long serialVersionUID = 1L;
        private final String className;

        ForeignThrowable(String className, String message) {
            super(message);
            this.className = className;
        }

        /** The original class's name, as its own toString would begin. */
        String className() {
            return className;
        }

        @Override
        public String toString() {
            String message = getLocalizedMessage();
            return message != null ? className + ": " + message : className;
        }
    }
}
