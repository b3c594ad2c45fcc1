package ray.bench;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A generated OBJ torus of {@code 2·rings·segments} triangles (1000 × 500 quads make 1M), written
 * once to a file, for the mesh load-time and memory figures. Positions only and "f a b c" faces,
 * the form most exported meshes take.
 */
final class LargeMesh {
    static final int RINGS = 1000;
    static final int SEGMENTS = 500;

    private LargeMesh() {
    }

    static int triangles() {
        return 2 * RINGS * SEGMENTS;
    }

    /** The OBJ file under {@code folder}, written if it is not there yet. */
    static Path file(Path folder) throws IOException {
        Path file = folder.resolve("torus-" + triangles() + ".obj");
        if (!Files.exists(file)) {
            Files.createDirectories(folder);
            Path partial = folder.resolve(file.getFileName() + ".part");
            try (BufferedWriter out = Files.newBufferedWriter(partial, StandardCharsets.US_ASCII)) {
                write(out);
            }
            Files.move(partial, file);
        }
        return file;
    }

    private static void write(BufferedWriter out) throws IOException {
        double major = 2;
        double minor = 0.6;
        out.write("# torus: " + RINGS + " x " + SEGMENTS + " quads, " + triangles() + " triangles\n");
        for (int i = 0; i < RINGS; i++) {
            double theta = 2 * Math.PI * i / RINGS;
            for (int k = 0; k < SEGMENTS; k++) {
                double phi = 2 * Math.PI * k / SEGMENTS;
                double ring = major + minor * Math.cos(phi);
                out.write("v " + (float) (ring * Math.cos(theta)) + " " + (float) (minor * Math.sin(phi)) + " "
                        + (float) (ring * Math.sin(theta)) + "\n");
            }
        }
        for (int i = 0; i < RINGS; i++) {
            for (int k = 0; k < SEGMENTS; k++) {
                int a = 1 + i * SEGMENTS + k;
                int b = 1 + i * SEGMENTS + (k + 1) % SEGMENTS;
                int c = 1 + ((i + 1) % RINGS) * SEGMENTS + (k + 1) % SEGMENTS;
                int d = 1 + ((i + 1) % RINGS) * SEGMENTS + k;
                out.write("f " + a + " " + b + " " + c + "\nf " + a + " " + c + " " + d + "\n");
            }
        }
    }
}
