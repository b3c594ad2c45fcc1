package ray.grading.judge;

import java.io.DataInputStream;
import java.io.FileOutputStream;
import java.io.FileDescriptor;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import ray.grading.wire.Protocol;
import ray.grading.wire.WireOut;

/**
 * A worker that misbehaves on purpose, for {@link WorkerStrictnessTest}: it starts as a worker does
 * (a READY frame) and answers each call as its first argument says. {@code ok} answers a byte 42;
 * {@code garbage} prints text where frames go; {@code huge} announces a frame of 2 GB; {@code silent}
 * never answers; {@code exit} exits; {@code leftover} answers with a byte too many; {@code wrongtype}
 * answers with a frame of an unknown type; {@code once:MODE:FILE} misbehaves as MODE the first time
 * (FILE marks that it did) and is {@code ok} after.
 */
public final class FakeWorker {
    private FakeWorker() {
    }

    public static void main(String[] args) throws IOException, InterruptedException {
        String mode = args[0];
        if (mode.startsWith("once:")) {
            String[] parts = mode.split(":", 3);
            Path marker = Path.of(parts[2]);
            mode = Files.exists(marker) ? "ok" : parts[1];
            Files.writeString(marker, "misbehaved");
        }
        OutputStream out = new FileOutputStream(FileDescriptor.out);
        new WireOut().str(Protocol.VERSION).send(out, Protocol.READY);
        DataInputStream in = new DataInputStream(System.in);
        while (true) {
            int type = in.read();
            if (type < 0) {
                return;
            }
            byte[] payload = new byte[in.readInt()];
            in.readFully(payload);
            switch (mode) {
                case "ok":
                    new WireOut().u8(42).send(out, Protocol.ANSWER);
                    break;
                case "garbage":
                    out.write("PASSED ray.surface.SphereTest#startIsExclusive\n".getBytes(StandardCharsets.US_ASCII));
                    out.flush();
                    break;
                case "huge":
                    out.write(new byte[] {(byte) Protocol.ANSWER, 0x7f, (byte) 0xff, (byte) 0xff, (byte) 0xff});
                    out.flush();
                    break;
                case "silent":
                    Thread.sleep(Long.MAX_VALUE);
                    break;
                case "exit":
                    System.exit(3);
                    break;
                case "leftover":
                    new WireOut().u8(42).u8(0).send(out, Protocol.ANSWER);
                    break;
                case "wrongtype":
                    new WireOut().u8(42).send(out, 99);
                    break;
                default:
                    throw new IllegalArgumentException(mode);
            }
        }
    }
}
