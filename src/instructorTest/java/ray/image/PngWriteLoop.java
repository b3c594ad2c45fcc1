package ray.image;

import java.nio.file.Path;
import ray.math.Vec3;

/**
 * A process for {@link PngWriterKillTest} to kill: writes the same target over and over, each time a
 * large image of one grey level (1, 2, 3, ...), announcing each write on standard output first.
 */
public final class PngWriteLoop {
    private PngWriteLoop() {
    }

    public static void main(String[] args) throws Exception {
        Path target = Path.of(args[0]);
        int side = Integer.parseInt(args[1]);
        for (int k = 1; ; k++) {
            Image image = new Image(side, side);
            Vec3 grey = new Vec3(k % 200 / 255.0, k % 200 / 255.0, k % 200 / 255.0);
            for (int j = 0; j < side; j++) {
                for (int i = 0; i < side; i++) {
                    image.set(i, j, grey);
                }
            }
            // Tone-mapped first, so that the announced write is the file write itself.
            java.awt.image.BufferedImage picture = PngWriter.toBufferedImage(image, 1);
            System.out.println("writing " + k);
            PngWriter.write(picture, target);
        }
    }
}
