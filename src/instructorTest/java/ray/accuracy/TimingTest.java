package ray.accuracy;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.util.concurrent.atomic.AtomicInteger;
import org.junit.Test;

public class TimingTest {
    @Test
    public void medianAndSpreadOfOddAndEvenRunCounts() {
        Timing three = Timing.of(0.30, 0.10, 0.20);
        assertEquals(0.20, three.medianSeconds, 0);
        assertEquals(0.10, three.minSeconds, 0);
        assertEquals(0.30, three.maxSeconds, 0);
        assertEquals(3, three.runs);
        Timing four = Timing.of(4, 1, 3, 2);
        assertEquals(2.5, four.medianSeconds, 0);
        assertEquals("one disturbed run does not move the median", 0.2, Timing.of(0.2, 9.0, 0.2).medianSeconds, 0);
        assertEquals("0.200 s (0.100–0.300 s, 3 runs)", three.toString());
    }

    @Test
    public void measureRunsTheWorkTheGivenNumberOfTimesAndKeepsTheLastResult() {
        AtomicInteger calls = new AtomicInteger();
        Object[] last = new Object[1];
        Timing.Timed<Object> timed = Timing.measure(3, () -> {
            calls.incrementAndGet();
            last[0] = new Object();
            return last[0];
        });
        assertEquals(3, calls.get());
        assertSame(last[0], timed.result);
        assertEquals(3, timed.timing.runs);
        assertTrue(timed.timing.minSeconds >= 0 && timed.timing.minSeconds <= timed.timing.medianSeconds
                && timed.timing.medianSeconds <= timed.timing.maxSeconds);
    }

    @Test
    public void impossibleTimingsAreRefused() {
        expect(() -> Timing.of(), "a timing needs at least one run");
        expect(() -> Timing.of(0.1, -1), "a run cannot take -1.0 seconds");
        expect(() -> Timing.of(Double.NaN), "a run cannot take NaN seconds");
        expect(() -> Timing.measure(0, Object::new), "runs must be at least 1, got 0");
    }

    private static void expect(Runnable r, String message) {
        try {
            r.run();
            fail("expected: " + message);
        } catch (IllegalArgumentException e) {
            assertEquals(message, e.getMessage());
        }
    }
}
