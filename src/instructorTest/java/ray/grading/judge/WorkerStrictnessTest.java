package ray.grading.judge;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertThrows;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.After;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.grading.wire.Protocol;

/**
 * A worker that answers out of format, too much, out of turn, not at all, or ends, fails the call
 * that waited for it with what happened, is ended, and the next call starts a fresh one: nothing it
 * sends is taken for an answer it did not give.
 */
public class WorkerStrictnessTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private Worker worker;

    @After
    public void endTheWorker() {
        Worker.stopIfStarted();
    }

    private Worker misbehaving(String mode) {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        // The fake's classes and the wire's: a short command line, which the tests read back.
        String classpath = where(FakeWorker.class) + File.pathSeparator + where(Protocol.class);
        Worker.use(new Containment(List.of(java, "-cp", classpath, FakeWorker.class.getName(), mode), Map.of(), null));
        return Worker.get();
    }

    private static String where(Class<?> type) {
        try {
            return Path.of(type.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (java.net.URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    /** One call whose answer is a single byte. */
    private static int call(Worker worker) {
        return worker.call(m -> m.body.u8(Protocol.OP_INTERSECT), in -> in.u8());
    }

    private WorkerFailure failure(String mode) {
        worker = misbehaving(mode);
        return assertThrows(WorkerFailure.class, () -> call(worker));
    }

    @Test
    public void aWellBehavedWorkerIsBelieved() {
        assertEquals(42, call(misbehaving("ok")));
    }

    @Test
    public void textWhereAnAnswerShouldBeFailsTheCall() {
        WorkerFailure e = failure("garbage");
        assertEquals(WorkerFailure.Kind.GARBLED, e.kind);
        assertTrue(e.getMessage(), e.getMessage().contains("or text: \"PASSED ray.surface.SphereTest"));
    }

    @Test
    public void aFrameLargerThanAllowedIsNotWaitedFor() {
        WorkerFailure e = failure("huge");
        assertTrue(e.getMessage(), e.getMessage().contains("a frame of 2147483647 bytes (allowed 100663296)"));
    }

    @Test
    public void anAnswerWithBytesLeftOverFailsTheCall() {
        WorkerFailure e = failure("leftover");
        assertEquals("the worker answered out of format (1 bytes left over after the message)", e.getMessage());
    }

    @Test
    public void aMessageOfAnUnknownTypeFailsTheCall() {
        assertEquals("the worker sent a message of type 99 out of turn", failure("wrongtype").getMessage());
    }

    @Test
    public void aWorkerThatEndsFailsTheCallSayingSo() {
        WorkerFailure e = failure("exit");
        assertEquals(WorkerFailure.Kind.ENDED, e.kind);
        assertTrue(e.getMessage(), e.getMessage().startsWith("the JVM running your code ended (exit code 3)"));
    }

    /** A test's time limit interrupts the wait: the call fails as timed out, and the worker's process is gone. */
    @Test(timeout = 60_000)
    public void aSilentWorkerIsEndedWhenTheTestsLimitComes() throws Exception {
        worker = misbehaving("silent");
        AtomicReference<Throwable> thrown = new AtomicReference<>();
        Thread test = new Thread(() -> {
            try {
                call(worker);
            } catch (Throwable t) {
                thrown.set(t);
            }
        });
        test.start();
        List<ProcessHandle> running = List.of();
        for (int wait = 0; wait < 300 && running.isEmpty(); wait++) {
            Thread.sleep(100);
            running = ProcessHandle.current().descendants().filter(p -> String.join(" ", p.info().arguments().orElse(new String[0]))
                    .contains(FakeWorker.class.getName())).collect(java.util.stream.Collectors.toList());
        }
        assertEquals("the worker runs", 1, running.size());
        Thread.sleep(500);
        test.interrupt();
        test.join(30_000);
        WorkerFailure e = (WorkerFailure) thrown.get();
        assertEquals(WorkerFailure.Kind.TIMED_OUT, e.kind);
        running.get(0).onExit().get(10, java.util.concurrent.TimeUnit.SECONDS);
    }

    /** After a failure, the next call starts another worker, which answers. */
    @Test
    public void theNextCallStartsAFreshWorker() {
        File marker = new File(folder.getRoot(), "misbehaved");
        worker = misbehaving("once:garbage:" + marker);
        assertThrows(WorkerFailure.class, () -> call(worker));
        assertTrue(marker.exists());
        assertEquals(42, call(worker));
    }
}
