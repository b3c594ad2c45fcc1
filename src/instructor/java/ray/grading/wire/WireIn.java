package ray.grading.wire;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import ray.math.Vec3;

/**
 * A message read from the other side, decoded strictly: every read past its end, every count out of
 * its bounds, every unknown tag and every byte left over is a {@link WireError}. The judge reads the
 * student's side with this and believes nothing it cannot parse exactly.
 */
public final class WireIn {
    private static final VarHandle LONG = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle INT = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.BIG_ENDIAN);

    private final byte[] bytes;
    private final int end;
    private int at;

    public WireIn(byte[] bytes) {
        this(bytes, bytes.length);
    }

    public WireIn(byte[] bytes, int length) {
        this.bytes = bytes;
        this.end = length;
    }

    private void need(int count) {
        if (end - at < count) {
            throw new WireError("the message ends " + (count - (end - at)) + " bytes early");
        }
    }

    public int u8() {
        need(1);
        return bytes[at++] & 0xff;
    }

    public boolean bool() {
        int b = u8();
        if (b > 1) {
            throw new WireError("a yes/no byte of " + b);
        }
        return b == 1;
    }

    public int i32() {
        need(4);
        int v = (int) INT.get(bytes, at);
        at += 4;
        return v;
    }

    /** A non-negative int written by {@link WireOut#varint}. */
    public int varint() {
        int value = 0;
        for (int shift = 0; shift < 35; shift += 7) {
            int b = u8();
            value |= (b & 0x7f) << shift;
            if ((b & 0x80) == 0) {
                if (value < 0) {
                    throw new WireError("a varint beyond an int's range");
                }
                return value;
            }
        }
        throw new WireError("a varint of more than five bytes");
    }

    public long i64() {
        need(8);
        long v = (long) LONG.get(bytes, at);
        at += 8;
        return v;
    }

    public double f64() {
        return Double.longBitsToDouble(i64());
    }

    /** A count from 0 to {@code max}, else a WireError naming {@code what}. */
    public int count(int max, String what) {
        int n = i32();
        if (n < 0 || n > max) {
            throw new WireError(what + ": a count of " + n + " (allowed 0 to " + max + ")");
        }
        return n;
    }

    /** An index into a table of {@code size} entries. */
    public int index(int size, String what) {
        int k = i32();
        if (k < 0 || k >= size) {
            throw new WireError(what + ": index " + k + " of a table of " + size);
        }
        return k;
    }

    /** A string of at most {@code maxBytes} UTF-8 bytes, or null. */
    public String str(int maxBytes) {
        int n = i32();
        if (n == -1) {
            return null;
        }
        if (n < 0 || n > maxBytes) {
            throw new WireError("a string of " + n + " bytes (allowed " + maxBytes + ")");
        }
        need(n);
        String s = new String(bytes, at, n, StandardCharsets.UTF_8);
        at += n;
        return s;
    }

    /** A vector or null ({@link WireOut#vec}). */
    public Vec3 vec() {
        return bool() ? new Vec3(f64(), f64(), f64()) : null;
    }

    /** Whether the message has more to read. */
    public boolean more() {
        return at < end;
    }

    /** The message must be read to its last byte. */
    public void end() {
        if (at != end) {
            throw new WireError((end - at) + " bytes left over after the message");
        }
    }
}
