package ray.grading.worker;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import ray.grading.wire.Frames;
import ray.grading.wire.Protocol;
import ray.grading.wire.ThrownData;
import ray.grading.wire.WireError;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;

/**
 * The worker's end of the pipe: it serves the judge's calls one at a time, and while one runs it
 * asks the judge about judge-side surfaces the student's code calls ({@link #callback}), serving any
 * call the judge makes meanwhile (a judge-side surface that holds a student's object).
 */
final class JudgeLink {
    private final InputStream in;
    private final OutputStream out;
    private final WorkerObjects objects;
    private final WorkerCalls calls;
    private final BatchCalls batches;
    /** The batch being answered, or null: a judge-side surface then answers from the batch's tables. */
    private BatchCalls.Running batch;
    /** How many calls are running (nested through callbacks): System.exit during one is reported. */
    private volatile int running;

    JudgeLink(InputStream in, OutputStream out) {
        this.in = in;
        this.out = out;
        this.objects = new WorkerObjects(this);
        this.calls = new WorkerCalls(objects, this);
        this.batches = new BatchCalls(objects, this);
    }

    BatchCalls.Running batch() {
        return batch;
    }

    void inBatch(BatchCalls.Running running) {
        this.batch = running;
    }

    /** Says the worker is ready: the version of the wire format it speaks. */
    void ready() throws IOException {
        send(Protocol.READY, new WireOut().str(Protocol.VERSION));
    }

    /** Serves the judge's messages until it closes the pipe. */
    void serve() throws IOException {
        while (true) {
            Frames.Frame frame = Frames.read(in);
            if (frame == null) {
                return;
            }
            if (frame.type == Protocol.CALLBACK_ANSWER) {
                throw new WireError("a callback answer with no callback asked");
            }
            handle(frame);
        }
    }

    private void handle(Frames.Frame frame) throws IOException {
        running++;
        try {
            switch (frame.type) {
                case Protocol.CALL:
                    send(Protocol.ANSWER, calls.call(frame.reader()));
                    break;
                case Protocol.BATCH:
                    if (batch != null) {
                        throw new WireError("a batch inside a batch");
                    }
                    send(Protocol.BATCH_ANSWER, batches.answer(frame.reader()));
                    break;
                default:
                    throw new WireError("a message of type " + frame.type);
            }
        } finally {
            running--;
        }
    }

    /**
     * Asks the judge something during a call ({@code request}: a callback's kind, then what it needs;
     * {@link Protocol#CB_INTERSECT}) and returns the answer, serving the judge's calls until it comes.
     */
    WireIn callback(WireOut request) {
        try {
            send(Protocol.CALLBACK, request);
            while (true) {
                Frames.Frame frame = Frames.read(in);
                if (frame == null) {
                    throw new WireError("the judge closed the pipe during a callback");
                }
                if (frame.type == Protocol.CALLBACK_ANSWER) {
                    return frame.reader();
                }
                handle(frame);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Asks the judge something during a call ({@link #callback}) and returns its answer, its
     * definitions taken in and read past the status: what the judge's side returned. What it threw is
     * thrown here, to pass through the student's code as it was ({@link JudgeSurface.JudgeSideThrew}).
     */
    WireIn ask(WireOut request) {
        WireIn answer = callback(request);
        objects.define(answer);
        int status = answer.u8();
        if (status == Protocol.THREW) {
            ThrownData thrown = ThrownData.read(answer);
            answer.end();
            throw new JudgeSurface.JudgeSideThrew(thrown);
        }
        if (status != Protocol.RETURNED) {
            throw new WireError("a callback answer of status " + status);
        }
        return answer;
    }

    private void send(int type, WireOut message) throws IOException {
        synchronized (out) {
            message.send(out, type);
        }
    }

    /** At the JVM's exit: when a call was running, the student's code called System.exit, and the judge is told. */
    void exiting() {
        if (running > 0) {
            try {
                send(Protocol.EXITING, new WireOut().str("System.exit"));
            } catch (IOException e) {
                // The judge sees the pipe close instead.
            }
        }
    }
}
