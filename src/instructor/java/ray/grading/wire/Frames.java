package ray.grading.wire;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;

/**
 * Grading's pipe carries frames: a type byte, the payload's length (4 bytes, big-endian) and the
 * payload. A reader takes a frame whole or not at all, and never more than {@link #MAX_FRAME_BYTES}:
 * a side that announces more is not believed.
 */
public final class Frames {
    /** The largest frame either side sends; the judge splits its batches to stay below it. */
    public static final int MAX_FRAME_BYTES = 96 << 20;

    private Frames() {
    }

    /** One frame as read: its type and payload. */
    public static final class Frame {
        public final int type;
        public final byte[] payload;

        Frame(int type, byte[] payload) {
            this.type = type;
            this.payload = payload;
        }

        public WireIn reader() {
            return new WireIn(payload);
        }
    }

    static void write(OutputStream out, int type, byte[] payload, int length) throws IOException {
        byte[] header = {(byte) type, (byte) (length >>> 24), (byte) (length >>> 16), (byte) (length >>> 8), (byte) length};
        out.write(header);
        out.write(payload, 0, length);
        out.flush();
    }

    /**
     * The next frame, or null at the end of the stream before a frame begins.
     *
     * @throws EOFException when the stream ends inside a frame
     * @throws WireError    when the frame announces more than {@link #MAX_FRAME_BYTES}
     */
    public static Frame read(InputStream in) throws IOException {
        int type = in.read();
        if (type < 0) {
            return null;
        }
        byte[] header = in.readNBytes(4);
        if (header.length < 4) {
            throw new EOFException("the stream ended inside a frame's header");
        }
        int length = (header[0] & 0xff) << 24 | (header[1] & 0xff) << 16 | (header[2] & 0xff) << 8 | header[3] & 0xff;
        if (length < 0 || length > MAX_FRAME_BYTES) {
            // Most likely text where a frame should be (something printed to the protocol's stream): show its start.
            // What has come already, without waiting for more (a sender that stops there is not waited for).
            byte[] more = in.readNBytes(Math.min(40, in.available()));
            byte[] start = new byte[5 + more.length];
            start[0] = (byte) type;
            System.arraycopy(header, 0, start, 1, 4);
            System.arraycopy(more, 0, start, 5, more.length);
            String text = new String(start, java.nio.charset.StandardCharsets.ISO_8859_1).replaceAll("[^\\x20-\\x7e]", "?");
            throw new WireError("a frame of " + Integer.toUnsignedString(length) + " bytes (allowed " + MAX_FRAME_BYTES + "), or text: \"" + text + "\"");
        }
        byte[] payload = in.readNBytes(length);
        if (payload.length < length) {
            throw new EOFException("the stream ended " + (length - payload.length) + " bytes into a frame");
        }
        return new Frame(type, payload);
    }
}
