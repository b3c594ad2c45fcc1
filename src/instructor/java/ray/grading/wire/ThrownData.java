package ray.grading.wire;

import java.util.ArrayList;
import java.util.List;

/**
 * What the student's code threw, as data: the class's name, the message, the stack frames and the
 * cause. The worker writes it; the judge rebuilds a throwable from it that the tests treat as they
 * would the original (ray.grading.judge.RethrownFromWorker), never loading the student's exception
 * class. Every name and message is cut to the protocol's limits on the way.
 */
public final class ThrownData {
    public final String className;
    public final String message;
    public final List<StackTraceElement> frames;
    public final ThrownData cause;

    public ThrownData(String className, String message, List<StackTraceElement> frames, ThrownData cause) {
        this.className = className;
        this.message = message;
        this.frames = List.copyOf(frames);
        this.cause = cause;
    }

    /**
     * The throwable's data, keeping the frames above {@code stopAt}'s first frame (the worker's own
     * code, which called the student's): the frames the student's call made, as in the judge's own
     * process the stack would show them.
     */
    public static ThrownData of(Throwable t, String stopAtClassPrefix) {
        return of(t, stopAtClassPrefix, 0);
    }

    private static ThrownData of(Throwable t, String stopAt, int depth) {
        List<StackTraceElement> frames = new ArrayList<>();
        for (StackTraceElement f : t.getStackTrace()) {
            if (f.getClassName().startsWith(stopAt) || frames.size() >= Protocol.MAX_FRAMES) {
                break;
            }
            frames.add(new StackTraceElement(Protocol.cutName(f.getClassName()), Protocol.cutName(f.getMethodName()),
                    f.getFileName() == null ? null : Protocol.cutName(f.getFileName()), f.getLineNumber()));
        }
        Throwable c = t.getCause();
        ThrownData cause = c != null && c != t && depth < Protocol.MAX_CAUSES ? of(c, stopAt, depth + 1) : null;
        String message;
        try {
            message = t.getMessage();
        } catch (RuntimeException | StackOverflowError e) {
            // The student's exception class chooses its getMessage: one that throws says so.
            message = "(its getMessage threw " + e.getClass().getName() + ")";
        }
        return new ThrownData(Protocol.cutName(t.getClass().getName()),
                message == null ? null : cut(message, Protocol.MAX_MESSAGE_BYTES / 4), frames, cause);
    }

    /** Characters of the message a brief one keeps. */
    private static final int BRIEF_MESSAGE_CHARS = 200;

    /** The same throwable in brief: its class and the start of its message, without frames or cause. */
    public ThrownData brief() {
        return new ThrownData(className, message == null ? null : cut(message, BRIEF_MESSAGE_CHARS), List.of(), null);
    }

    /** About how many bytes {@link #write} writes (at most four per character). */
    public long estimatedBytes() {
        long bytes = 16L + 4L * (className.length() + (message == null ? 0 : message.length()));
        for (StackTraceElement f : frames) {
            bytes += 16L + 4L * (f.getClassName().length() + f.getMethodName().length() + (f.getFileName() == null ? 0 : f.getFileName().length()));
        }
        return bytes + (cause == null ? 0 : cause.estimatedBytes());
    }

    /** At most {@code chars} characters, so that the UTF-8 bytes stay within four times that. */
    private static String cut(String s, int chars) {
        return s.length() <= chars ? s : s.substring(0, chars);
    }

    public void write(WireOut out) {
        out.str(className).str(message).i32(frames.size());
        for (StackTraceElement f : frames) {
            out.str(f.getClassName()).str(f.getMethodName()).str(f.getFileName()).i32(f.getLineNumber());
        }
        out.bool(cause != null);
        if (cause != null) {
            cause.write(out);
        }
    }

    public static ThrownData read(WireIn in) {
        return read(in, 0);
    }

    private static ThrownData read(WireIn in, int depth) {
        String className = in.str(Protocol.MAX_NAME_BYTES);
        if (className == null || !className.matches("[\\p{L}\\p{N}_$.]{1,200}")) {
            throw new WireError("an exception class name that is no Java name");
        }
        String message = in.str(Protocol.MAX_MESSAGE_BYTES);
        int n = in.count(Protocol.MAX_FRAMES, "stack frames");
        List<StackTraceElement> frames = new ArrayList<>(n);
        for (int k = 0; k < n; k++) {
            String declaring = in.str(Protocol.MAX_NAME_BYTES);
            String method = in.str(Protocol.MAX_NAME_BYTES);
            if (declaring == null || method == null) {
                throw new WireError("a stack frame without a class or method");
            }
            frames.add(new StackTraceElement(declaring, method, in.str(Protocol.MAX_NAME_BYTES), in.i32()));
        }
        ThrownData cause = null;
        if (in.bool()) {
            if (depth >= Protocol.MAX_CAUSES) {
                throw new WireError("causes nested more than " + Protocol.MAX_CAUSES + " deep");
            }
            cause = read(in, depth + 1);
        }
        return new ThrownData(className, message, frames, cause);
    }
}
