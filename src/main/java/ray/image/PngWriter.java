package ray.image;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import javax.imageio.ImageIO;

/** Writes an image as an 8-bit sRGB-less PNG (gamma 2.2 encoded by {@link ToneMap}), atomically. */
public final class PngWriter {
    /**
     * Temporary files being written. Ctrl-C (SIGINT) or a kill (SIGTERM) ends the JVM without running
     * the writing thread's finally block, but it does run shutdown hooks: the hook removes these.
     * After SIGKILL or a power cut a hidden ".NAME.png*.tmp" may stay; the target is whole either way.
     */
    private static final Set<Path> IN_FLIGHT = ConcurrentHashMap.newKeySet();

    static {
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            for (Path temporary : IN_FLIGHT) {
                try {
                    Files.deleteIfExists(temporary);
                } catch (IOException e) {
                    // The JVM is ending; a leftover hidden temporary is all that can go wrong.
                }
            }
        }, "png-writer-cleanup"));
    }

    private PngWriter() {
    }

    /** The tone-mapped 8-bit picture; the PNG's first row is the image's top row (j = height − 1). */
    public static BufferedImage toBufferedImage(Image image, double exposure) {
        BufferedImage out = new BufferedImage(image.width(), image.height(), BufferedImage.TYPE_INT_RGB);
        for (int j = 0; j < image.height(); j++) {
            int row = image.height() - 1 - j;
            for (int i = 0; i < image.width(); i++) {
                ray.math.Vec3 c = image.get(i, j);
                int r = ToneMap.toByte(c.x, exposure);
                int g = ToneMap.toByte(c.y, exposure);
                int b = ToneMap.toByte(c.z, exposure);
                out.setRGB(i, row, (r << 16) | (g << 8) | b);
            }
        }
        return out;
    }

    /**
     * Writes the PNG to a temporary file beside {@code target} and renames it into place, so that
     * a crash never leaves a truncated file and an existing one is only replaced by a complete one.
     */
    public static void write(Image image, double exposure, Path target) throws IOException {
        write(toBufferedImage(image, exposure), target);
    }

    public static void write(BufferedImage picture, Path target) throws IOException {
        Path folder = target.toAbsolutePath().getParent();
        Files.createDirectories(folder);
        Path temporary = Files.createTempFile(folder, "." + target.getFileName(), ".tmp");
        IN_FLIGHT.add(temporary);
        try {
            if (!ImageIO.write(picture, "png", temporary.toFile())) {
                throw new IOException("no PNG writer is available");
            }
            try {
                Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            Files.deleteIfExists(temporary);
            IN_FLIGHT.remove(temporary);
        }
    }
}
