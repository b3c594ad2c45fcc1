package ray.grading.wire;

import java.io.IOException;
import java.io.OutputStream;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import ray.math.Vec3;

/**
 * A message being written for the other side of grading's pipe: numbers big-endian, doubles by
 * their exact bits, so that the student's code sees the very values the tests chose. Sent whole, as
 * one frame ({@link Frames}).
 */
public final class WireOut {
    private static final VarHandle LONG = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle INT = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.BIG_ENDIAN);

    private byte[] bytes = new byte[512];
    private int size;

    /** Empties the message, keeping its buffer. */
    public WireOut clear() {
        size = 0;
        return this;
    }

    public int size() {
        return size;
    }

    private void room(int more) {
        if (size + more > bytes.length) {
            long wanted = Math.max((long) bytes.length * 2, (long) size + more);
            if (wanted > Frames.MAX_FRAME_BYTES) {
                throw new WireError("a message of more than " + Frames.MAX_FRAME_BYTES + " bytes");
            }
            bytes = Arrays.copyOf(bytes, (int) wanted);
        }
    }

    public WireOut u8(int value) {
        room(1);
        bytes[size++] = (byte) value;
        return this;
    }

    public WireOut bool(boolean value) {
        return u8(value ? 1 : 0);
    }

    public WireOut i32(int value) {
        room(4);
        INT.set(bytes, size, value);
        size += 4;
        return this;
    }

    /** A non-negative int in 7-bit groups, low first (LEB128): one byte below 128, the usual count or index. */
    public WireOut varint(int value) {
        if (value < 0) {
            throw new IllegalArgumentException("a varint of " + value);
        }
        while (value >= 0x80) {
            u8(value & 0x7f | 0x80);
            value >>>= 7;
        }
        return u8(value);
    }

    public WireOut i64(long value) {
        room(8);
        LONG.set(bytes, size, value);
        size += 8;
        return this;
    }

    /** A double by its raw bits: NaN payloads and −0.0 arrive as they left. */
    public WireOut f64(double value) {
        return i64(Double.doubleToRawLongBits(value));
    }

    /** A string as UTF-8 bytes after their count; null as −1. */
    public WireOut str(String value) {
        if (value == null) {
            return i32(-1);
        }
        byte[] utf8 = value.getBytes(StandardCharsets.UTF_8);
        i32(utf8.length);
        room(utf8.length);
        System.arraycopy(utf8, 0, bytes, size, utf8.length);
        size += utf8.length;
        return this;
    }

    /** A vector, or null: a presence byte, then its three coordinates. */
    public WireOut vec(Vec3 v) {
        if (v == null) {
            return u8(0);
        }
        u8(1);
        return f64(v.x).f64(v.y).f64(v.z);
    }

    /** Overwrites the four bytes at {@code at} (a count written before its entries were known). */
    public WireOut patchI32(int at, int value) {
        bytes[at] = (byte) (value >>> 24);
        bytes[at + 1] = (byte) (value >>> 16);
        bytes[at + 2] = (byte) (value >>> 8);
        bytes[at + 3] = (byte) value;
        return this;
    }

    /** Appends everything written to {@code other} so far. */
    public WireOut raw(WireOut other) {
        room(other.size);
        System.arraycopy(other.bytes, 0, bytes, size, other.size);
        size += other.size;
        return this;
    }

    /** A copy of what was written. */
    public byte[] toByteArray() {
        return Arrays.copyOf(bytes, size);
    }

    /** Writes the message as one frame of {@code type}. */
    public void send(OutputStream out, int type) throws IOException {
        Frames.write(out, type, bytes, size);
    }
}
