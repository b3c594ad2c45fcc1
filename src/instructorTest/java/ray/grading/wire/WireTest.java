package ray.grading.wire;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertThrows;
import static org.junit.Assert.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.util.Random;
import org.junit.Test;
import ray.math.Vec3;

/**
 * The judge reads what a worker sends strictly: every value as the layout says, of the size it
 * allows, and nothing left over; anything else is a {@link WireError}, never a value made up.
 */
public class WireTest {
    /** Seeded random values of every kind come back bit for bit, NaNs, infinities and −0 included. */
    /**
     * However the student's code answers, an answer fits one frame: a throwable in brief with the
     * longest names and message and a hit with a foreign surface of the longest name stay within
     * {@link Batches#ANSWER_BYTES_AT_MOST}, and the budgets together stay below the frame's limit.
     */
    @Test
    public void theLargestAnswerFitsAFrame() {
        String longName = "\u4e00".repeat(70_000); // three UTF-8 bytes a character, longer than any limit
        ThrownData whole = ThrownData.of(new IllegalStateException(longName), "no.such.package");
        ThrownData brief = new ThrownData(Protocol.cutName(longName), longName, java.util.List.of(), null).brief();
        WireOut thrown = new WireOut();
        Answer.threw(brief).write(thrown, null);
        assertTrue(thrown.size() + " bytes", thrown.size() <= Batches.ANSWER_BYTES_AT_MOST);
        assertTrue(whole.estimatedBytes() > brief.estimatedBytes());
        WireOut hit = new WireOut();
        hit.u8(Protocol.RETURNED).bool(true).u8(0xff).f64(1).vec(new Vec3(1, 2, 3)).vec(new Vec3(1, 2, 3))
                .u8(Protocol.REF_FOREIGN).str(Protocol.cutName(longName)).f64(1).f64(1).f64(1).f64(1).u8(3).f64(0).f64(1);
        assertTrue(hit.size() + " bytes", hit.size() <= Batches.ANSWER_BYTES_AT_MOST);
        WireOut wholeOut = new WireOut();
        whole.write(wholeOut);
        long oneRaysSpeculation = (long) Batches.MAX_CANDIDATES * Batches.MAX_SEARCHED * Batches.ANSWER_BYTES_AT_MOST;
        long largest = Batches.ASKED_ANSWER_BYTES + Batches.THROWN_BYTES + wholeOut.size() + Batches.SPECULATED_BYTES + oneRaysSpeculation;
        assertTrue(largest + " bytes", largest < Frames.MAX_FRAME_BYTES);
    }

    @Test
    public void everyValueComesBackBitForBit() {
        Random random = new Random(40);
        double[] specials = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, -0.0, Double.MIN_VALUE, Double.MAX_VALUE};
        for (int round = 0; round < 2000; round++) {
            int i = random.nextInt();
            int v = random.nextInt(Integer.MAX_VALUE);
            long l = random.nextLong();
            double d = round < specials.length ? specials[round] : Double.longBitsToDouble(random.nextLong());
            String s = round % 7 == 0 ? null : "é" + Integer.toString(random.nextInt(), 36) + "\u2028";
            Vec3 vec = round % 5 == 0 ? null : new Vec3(random.nextGaussian(), d, -0.0);
            WireOut out = new WireOut().u8(round & 0xff).bool(round % 2 == 0).i32(i).varint(v).i64(l).f64(d).str(s).vec(vec);
            WireIn in = new WireIn(out.toByteArray());
            assertEquals(round & 0xff, in.u8());
            assertEquals(round % 2 == 0, in.bool());
            assertEquals(i, in.i32());
            assertEquals(v, in.varint());
            assertEquals(l, in.i64());
            assertEquals(Double.doubleToRawLongBits(d), Double.doubleToRawLongBits(in.f64()));
            assertEquals(s, in.str(1000));
            Vec3 back = in.vec();
            if (vec == null) {
                assertNull(back);
            } else {
                assertEquals(Double.doubleToRawLongBits(vec.x), Double.doubleToRawLongBits(back.x));
                assertEquals(Double.doubleToRawLongBits(vec.y), Double.doubleToRawLongBits(back.y));
                assertEquals(Double.doubleToRawLongBits(vec.z), Double.doubleToRawLongBits(back.z));
            }
            in.end();
        }
    }

    @Test
    public void aMessageThatEndsEarlyIsAnError() {
        byte[] bytes = new WireOut().i64(7).toByteArray();
        WireError e = assertThrows(WireError.class, () -> new WireIn(bytes, 5).i64());
        assertEquals("the message ends 3 bytes early", e.getMessage());
    }

    @Test
    public void bytesLeftOverAreAnError() {
        WireIn in = new WireIn(new WireOut().i32(1).u8(2).toByteArray());
        in.i32();
        assertEquals("1 bytes left over after the message", assertThrows(WireError.class, in::end).getMessage());
    }

    @Test
    public void aYesOrNoIsZeroOrOne() {
        assertEquals("a yes/no byte of 2", assertThrows(WireError.class, () -> new WireIn(new byte[] {2}).bool()).getMessage());
    }

    @Test
    public void countsIndicesAndStringsStayWithinTheirLimits() {
        assertEquals("rays: a count of 11 (allowed 0 to 10)",
                assertThrows(WireError.class, () -> new WireIn(new WireOut().i32(11).toByteArray()).count(10, "rays")).getMessage());
        assertEquals("rays: a count of -1 (allowed 0 to 10)",
                assertThrows(WireError.class, () -> new WireIn(new WireOut().i32(-1).toByteArray()).count(10, "rays")).getMessage());
        assertEquals("targets: index 3 of a table of 3",
                assertThrows(WireError.class, () -> new WireIn(new WireOut().i32(3).toByteArray()).index(3, "targets")).getMessage());
        assertEquals("a string of 9 bytes (allowed 8)",
                assertThrows(WireError.class, () -> new WireIn(new WireOut().str("123456789").toByteArray()).str(8)).getMessage());
        // A length beyond the message: an error, not a huge allocation.
        assertEquals("the message ends 996 bytes early",
                assertThrows(WireError.class, () -> new WireIn(new WireOut().i32(1000).i32(0).toByteArray()).str(1 << 20)).getMessage());
    }

    @Test
    public void aVarintIsAtMostFiveBytesAndNonNegative() {
        assertEquals("a varint of more than five bytes", assertThrows(WireError.class,
                () -> new WireIn(new byte[] {(byte) 0x80, (byte) 0x80, (byte) 0x80, (byte) 0x80, (byte) 0x80, 1}).varint()).getMessage());
        assertEquals("a varint beyond an int's range", assertThrows(WireError.class,
                () -> new WireIn(new byte[] {(byte) 0xff, (byte) 0xff, (byte) 0xff, (byte) 0xff, 0x0f}).varint()).getMessage());
    }

    @Test
    public void framesComeBackWhole() throws Exception {
        ByteArrayOutputStream pipe = new ByteArrayOutputStream();
        new WireOut().str("hello").send(pipe, Protocol.ANSWER);
        new WireOut().send(pipe, Protocol.READY);
        ByteArrayInputStream in = new ByteArrayInputStream(pipe.toByteArray());
        Frames.Frame first = Frames.read(in);
        assertEquals(Protocol.ANSWER, first.type);
        assertEquals("hello", first.reader().str(10));
        Frames.Frame second = Frames.read(in);
        assertEquals(Protocol.READY, second.type);
        assertEquals(0, second.payload.length);
        assertNull("the end of the stream between frames", Frames.read(in));
    }

    /** Text printed where frames go (a student's System.out on the pipe) is named as such, never read as a giant frame. */
    @Test
    public void textWhereAFrameShouldBeIsShownNotBelieved() {
        byte[] text = "Hello from my sphere, t = 4.0\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        WireError e = assertThrows(WireError.class, () -> Frames.read(new ByteArrayInputStream(text)));
        assertTrue(e.getMessage(), e.getMessage().startsWith("a frame of 1701604463 bytes (allowed 100663296), or text: \"Hello from my sphere"));
    }

    @Test
    public void aFrameCutShortIsAnEndOfStream() {
        ByteArrayOutputStream pipe = new ByteArrayOutputStream();
        pipe.writeBytes(new byte[] {(byte) Protocol.ANSWER, 0, 0, 0, 10, 1, 2, 3});
        EOFException e = assertThrows(EOFException.class, () -> Frames.read(new ByteArrayInputStream(pipe.toByteArray())));
        assertEquals("the stream ended 7 bytes into a frame", e.getMessage());
        assertEquals("the stream ended inside a frame's header", assertThrows(EOFException.class,
                () -> Frames.read(new ByteArrayInputStream(new byte[] {1, 0, 0}))).getMessage());
    }
}
