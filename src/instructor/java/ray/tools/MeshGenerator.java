package ray.tools;

import java.io.IOException;
import java.io.PrintWriter;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import ray.math.Vec3;
import ray.surface.MeshData;

/**
 * Writes the small OBJ meshes that the shipped scenes use, deterministically (same bytes on every
 * run and machine: Java floating point is strict, and numbers are printed rounded to 6 decimals).
 *
 * <p>Each mesh exercises a different part of {@code ray.scene.ObjReader}:
 * <ul>
 * <li>{@code torus-flat.obj}: quads {@code f a b c d} (split into fans), no normals, so each
 *     triangle shows its face normal;</li>
 * <li>{@code torus-smooth.obj}: the same quads with analytic vertex normals, {@code f a//a ...};</li>
 * <li>{@code vase.obj}: a surface of revolution in the full {@code f v/vt/vn} form, plus a bottom
 *     cap written as one flat 24-gon without normals (a big fan, flat inside a smooth mesh);</li>
 * <li>{@code checker.obj}: the dark squares of a checkerboard, each face written with negative
 *     (relative) indices {@code f -4 -3 -2 -1}.</li>
 * <li>{@code icosphere-room.obj}: a closed mesh to be seen from inside (scenes/hard), an icosahedron
 *     subdivided twice, wound inward.</li>
 * <li>{@code tablecloth.obj}: a square of two triangles, {@code f v/vt} faces, whose texture
 *     coordinates run over four units (u from 0 to 4, v from −3 to 1), so a repeating texture tiles
 *     it 4 × 4 times (scenes/textured).</li>
 * <li>{@code square-repeat.obj} and {@code square-clamp.obj}: a square of two triangles facing +z,
 *     {@code f v/vt} faces, whose texture coordinates cross the image's edges (the diagnostic
 *     chart, scenes/textured/diagnostic.xml).</li>
 * </ul>
 *
 * <p>Every face is wound counter-clockwise seen from outside, so the geometric normal
 * (v1 − v0) × (v2 − v0) points outward, as the renderer expects (it never flips normals); the
 * room's "outside" is its inside, where its camera and light are.
 *
 * <p>Usage: {@code java -cp build/classes/java/main ray.tools.MeshGenerator [FOLDER]} (default
 * {@code scenes/meshes}).
 */
public final class MeshGenerator {
    private static final String REGENERATE = "java -cp build/classes/java/main ray.tools.MeshGenerator scenes/meshes";

    private MeshGenerator() {
    }

    public static void main(String[] args) throws IOException {
        Path folder = Path.of(args.length > 0 ? args[0] : "scenes/meshes");
        Files.createDirectories(folder);
        writeTorus(folder.resolve("torus-flat.obj"), false);
        writeTorus(folder.resolve("torus-smooth.obj"), true);
        writeVase(folder.resolve("vase.obj"));
        writeChecker(folder.resolve("checker.obj"));
        writeIcosphereRoom(folder.resolve("icosphere-room.obj"));
        writeTablecloth(folder.resolve("tablecloth.obj"));
        // The diagnostic chart's squares: Repeat across the image's right and bottom edges, with u and
        // 1 − v never below −½ texel (where (int) and Math.floor part, and correct lookups with them);
        // Clamp beyond all four edges.
        writeSquare(folder.resolve("square-repeat.obj"), 0, 1.5, -0.5, 1);
        writeSquare(folder.resolve("square-clamp.obj"), -0.25, 1.25, -0.25, 1.25);
    }

    // Torus: major radius R (center of the tube to the y axis), minor radius r (the tube), lying in
    // the xz plane around the y axis. θ goes around the y axis, φ around the tube:
    //   p(θ, φ) = ((R + r cos φ) cos θ, r sin φ, (R + r cos φ) sin θ)
    // and the outward unit normal is the direction from the tube's center circle to p:
    //   n(θ, φ) = (cos φ cos θ, sin φ, cos φ sin θ).
    // ∂p/∂φ × ∂p/∂θ = r (R + r cos φ) n, so a quad listed in the order (θ, φ), (θ, φ+), (θ+, φ+), (θ+, φ)
    // turns counter-clockwise seen from outside. Its four corners are mirror images across the plane
    // of the middle θ, so they are coplanar and both fan triangles share one face normal.
    private static final double TORUS_MAJOR = 1.0;
    private static final double TORUS_MINOR = 0.4;
    private static final int TORUS_AROUND = 24;
    private static final int TORUS_TUBE = 12;

    private static void writeTorus(Path file, boolean withNormals) throws IOException {
        try (PrintWriter out = open(file)) {
            header(out, file, String.format("torus, R = %s, r = %s, %d x %d quads (%d triangles), %s",
                    num(TORUS_MAJOR), num(TORUS_MINOR), TORUS_AROUND, TORUS_TUBE, 2 * TORUS_AROUND * TORUS_TUBE,
                    withNormals ? "analytic vertex normals (smooth shading)" : "no normals (flat shading)"));
            // Vertex (i, j) is number 1 + i·TUBE + j; the grid wraps around in both directions.
            for (int i = 0; i < TORUS_AROUND; i++) {
                double theta = 2 * Math.PI * i / TORUS_AROUND;
                for (int j = 0; j < TORUS_TUBE; j++) {
                    double phi = 2 * Math.PI * j / TORUS_TUBE;
                    double ring = TORUS_MAJOR + TORUS_MINOR * Math.cos(phi);
                    vertex(out, "v", ring * Math.cos(theta), TORUS_MINOR * Math.sin(phi), ring * Math.sin(theta));
                }
            }
            if (withNormals) {
                for (int i = 0; i < TORUS_AROUND; i++) {
                    double theta = 2 * Math.PI * i / TORUS_AROUND;
                    for (int j = 0; j < TORUS_TUBE; j++) {
                        double phi = 2 * Math.PI * j / TORUS_TUBE;
                        vertex(out, "vn", Math.cos(phi) * Math.cos(theta), Math.sin(phi), Math.cos(phi) * Math.sin(theta));
                    }
                }
            }
            for (int i = 0; i < TORUS_AROUND; i++) {
                int nextI = (i + 1) % TORUS_AROUND;
                for (int j = 0; j < TORUS_TUBE; j++) {
                    int nextJ = (j + 1) % TORUS_TUBE;
                    int[] quad = {
                        1 + i * TORUS_TUBE + j, 1 + i * TORUS_TUBE + nextJ,
                        1 + nextI * TORUS_TUBE + nextJ, 1 + nextI * TORUS_TUBE + j,
                    };
                    StringBuilder face = new StringBuilder("f");
                    for (int k : quad) {
                        // The normals were written in the same order as the positions: normal k belongs to vertex k.
                        face.append(' ').append(k);
                        if (withNormals) {
                            face.append("//").append(k);
                        }
                    }
                    out.println(face);
                }
            }
        }
    }

    // Vase: the profile curve (ρ(s), y(s)), s in [0, 1], turned about the y axis:
    //   p(θ, s) = (ρ(s) cos θ, y(s), ρ(s) sin θ), with y(s) = H·s and
    //   ρ(s) = 0.34 + 0.2 sin(4.7 s − 0.3) + 0.18 s^8   (a foot, a belly, a neck and a flared lip).
    // ∂p/∂s × ∂p/∂θ = ρ (H cos θ, −ρ'(s), H sin θ), so the outward unit normal is
    //   n = normalize(H cos θ, −ρ'(s), H sin θ),  ρ'(s) = 0.94 cos(4.7 s − 0.3) + 1.44 s^7,
    // and quads ordered (θ, s), (θ, s+), (θ+, s+), (θ+, s) face outward, as on the torus.
    // The seam column θ = 2π repeats θ = 0 with texture coordinate u = 1 instead of 0.
    private static final double VASE_HEIGHT = 1.5;
    private static final int VASE_AROUND = 24;
    private static final int VASE_ALONG = 12;

    private static double vaseRadius(double s) {
        return 0.34 + 0.2 * Math.sin(4.7 * s - 0.3) + 0.18 * Math.pow(s, 8);
    }

    private static double vaseRadiusSlope(double s) {
        return 0.2 * 4.7 * Math.cos(4.7 * s - 0.3) + 0.18 * 8 * Math.pow(s, 7);
    }

    private static void writeVase(Path file) throws IOException {
        try (PrintWriter out = open(file)) {
            header(out, file, String.format("vase (surface of revolution), height %s, %d x %d quads + a %d-gon bottom cap"
                    + " (%d triangles), v/vt/vn faces; the cap has no normals",
                    num(VASE_HEIGHT), VASE_AROUND, VASE_ALONG, VASE_AROUND,
                    2 * VASE_AROUND * VASE_ALONG + VASE_AROUND - 2));
            int columns = VASE_AROUND + 1;
            int rows = VASE_ALONG + 1;
            // Vertex, texture coordinate and normal (i, j) are all number 1 + i·rows + j.
            for (int i = 0; i < columns; i++) {
                double theta = 2 * Math.PI * (i % VASE_AROUND) / VASE_AROUND;
                for (int j = 0; j < rows; j++) {
                    double s = (double) j / VASE_ALONG;
                    double rho = vaseRadius(s);
                    vertex(out, "v", rho * Math.cos(theta), VASE_HEIGHT * s, rho * Math.sin(theta));
                }
            }
            for (int i = 0; i < columns; i++) {
                for (int j = 0; j < rows; j++) {
                    out.println("vt " + num((double) i / VASE_AROUND) + " " + num((double) j / VASE_ALONG));
                }
            }
            for (int i = 0; i < columns; i++) {
                double theta = 2 * Math.PI * (i % VASE_AROUND) / VASE_AROUND;
                for (int j = 0; j < rows; j++) {
                    double s = (double) j / VASE_ALONG;
                    double nx = VASE_HEIGHT * Math.cos(theta);
                    double ny = -vaseRadiusSlope(s);
                    double nz = VASE_HEIGHT * Math.sin(theta);
                    double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
                    vertex(out, "vn", nx / length, ny / length, nz / length);
                }
            }
            out.println("g side");
            for (int i = 0; i < VASE_AROUND; i++) {
                for (int j = 0; j < VASE_ALONG; j++) {
                    int a = 1 + i * rows + j;
                    int b = a + 1;
                    int c = b + rows;
                    int d = a + rows;
                    out.println("f " + full(a) + " " + full(b) + " " + full(c) + " " + full(d));
                }
            }
            // The bottom ring in order of increasing θ, from +x toward +z: (v1 − v0) × (v2 − v0) points
            // along −y (e.g. ((0,0,1) − (1,0,0)) × ((−1,0,0) − (1,0,0)) = (0,−2,0)), outward for a bottom.
            out.println("g bottom");
            StringBuilder cap = new StringBuilder("f");
            for (int i = 0; i < VASE_AROUND; i++) {
                cap.append(' ').append(1 + i * rows);
            }
            out.println(cap);
        }
    }

    private static String full(int k) {
        return k + "/" + k + "/" + k;
    }

    // Checker: the dark squares of an N×N board of unit squares in the plane y = 0, centered on the
    // origin: square (i, j) is dark when i + j is even. Each square lists its own four corners and
    // then refers to them by negative indices (−1 is the latest vertex). Corners in the order
    // (x0, z0), (x0, z1), (x1, z1), (x1, z0) turn counter-clockwise seen from above, so the normal is +y.
    private static final int CHECKER_SIDE = 12;

    private static void writeChecker(Path file) throws IOException {
        try (PrintWriter out = open(file)) {
            int darkSquares = (CHECKER_SIDE * CHECKER_SIDE + 1) / 2;
            header(out, file, String.format("the dark squares of a %d x %d checkerboard of unit squares in y = 0,"
                    + " centered on the origin (%d triangles); faces use negative indices",
                    CHECKER_SIDE, CHECKER_SIDE, 2 * darkSquares));
            double half = CHECKER_SIDE / 2.0;
            for (int i = 0; i < CHECKER_SIDE; i++) {
                for (int j = 0; j < CHECKER_SIDE; j++) {
                    if ((i + j) % 2 != 0) {
                        continue;
                    }
                    double x0 = i - half;
                    double z0 = j - half;
                    vertex(out, "v", x0, 0, z0);
                    vertex(out, "v", x0, 0, z0 + 1);
                    vertex(out, "v", x0 + 1, 0, z0 + 1);
                    vertex(out, "v", x0 + 1, 0, z0);
                    out.println("f -4 -3 -2 -1");
                }
            }
        }
    }

    // Icosphere room: ray.tools.Icosphere subdivided twice on the unit sphere (320 triangles, 162
    // shared vertices), a closed mesh. Its faces are listed reversed, clockwise seen from outside,
    // so that (v1 − v0) × (v2 − v0) points toward the center: a room lit and seen from inside.
    private static final int ICOSPHERE_SUBDIVISIONS = 2;

    private static void writeIcosphereRoom(Path file) throws IOException {
        MeshData room = Icosphere.of(ICOSPHERE_SUBDIVISIONS, Vec3.ZERO, 1);
        int[] faces = room.triangles;
        try (PrintWriter out = open(file)) {
            header(out, file, String.format("an icosahedron subdivided %d times on the unit sphere (%d triangles,"
                    + " %d shared vertices), wound inward: a closed room to be lit and seen from inside",
                    ICOSPHERE_SUBDIVISIONS, faces.length / 3, room.vertexCount()));
            double[] p = room.positions;
            for (int i = 0; i < p.length; i += 3) {
                vertex(out, "v", p[i], p[i + 1], p[i + 2]);
            }
            for (int f = 0; f < faces.length; f += 3) {
                // Reversed (a, c, b): clockwise seen from outside, counter-clockwise from the center.
                out.println("f " + (faces[f] + 1) + " " + (faces[f + 2] + 1) + " " + (faces[f + 1] + 1));
            }
        }
    }

    // Tablecloth: the square [−1, 1]² in the plane y = 0 with texture coordinates u = 2(x + 1) and
    // v = 2(1 − z), 0 to 4: u grows toward +x and v away from a camera on the +z side, so a texture
    // appears upright, unmirrored, seen from there. Corners (−1, 1), (1, 1), (1, −1), (−1, −1) turn
    // counter-clockwise seen from above: the normal is +y.
    private static final double TABLECLOTH_REPEATS = 4;

    private static void writeTablecloth(Path file) throws IOException {
        try (PrintWriter out = open(file)) {
            header(out, file, String.format("the square [-1, 1]^2 in y = 0 (2 triangles), u from 0 to %s and v from %s to 1,"
                    + " f v/vt faces", num(TABLECLOTH_REPEATS), num(1 - TABLECLOTH_REPEATS)));
            double[][] corners = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}};
            for (double[] c : corners) {
                vertex(out, "v", c[0], 0, c[1]);
            }
            for (double[] c : corners) {
                double u = TABLECLOTH_REPEATS * (c[0] + 1) / 2;
                // v ends at 1, not starts at 0: above 1 + ½ texel the course's (int) and Math.floor
                // pick different rows, and both are correct lookups, so no shipped scene goes there.
                double v = 1 - TABLECLOTH_REPEATS + TABLECLOTH_REPEATS * (1 - c[1]) / 2;
                out.println("vt " + num(u) + " " + num(v));
            }
            out.println("f 1/1 2/2 3/3 4/4");
        }
    }

    /** The square [-1, 1]² in z = 0, facing +z, with u from u0 (left) to u1 and v from v0 (bottom) to v1. */
    private static void writeSquare(Path file, double u0, double u1, double v0, double v1) throws IOException {
        try (PrintWriter out = open(file)) {
            header(out, file, "the square [-1, 1]^2 in z = 0 facing +z (2 triangles), u from " + num(u0) + " to " + num(u1)
                    + " left to right, v from " + num(v0) + " to " + num(v1) + " bottom to top, f v/vt faces");
            double[][] corners = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            for (double[] c : corners) {
                vertex(out, "v", c[0], c[1], 0);
            }
            for (double[] c : corners) {
                out.println("vt " + num(c[0] < 0 ? u0 : u1) + " " + num(c[1] < 0 ? v0 : v1));
            }
            out.println("f 1/1 2/2 3/3 4/4");
        }
    }

    private static PrintWriter open(Path file) throws IOException {
        // "\n" line ends on every platform, so the files are byte-identical wherever they are made.
        return new PrintWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            @Override
            public void println() {
                write('\n');
            }
        };
    }

    private static void header(PrintWriter out, Path file, String description) {
        out.println("# " + file.getFileName() + ": " + description + ".");
        out.println("# Generated by ray.tools.MeshGenerator; do not edit. To regenerate (from the repository root):");
        out.println("#   " + REGENERATE);
    }

    private static void vertex(PrintWriter out, String kind, double x, double y, double z) {
        out.println(kind + " " + num(x) + " " + num(y) + " " + num(z));
    }

    /** A number rounded to 6 decimals, without trailing zeros or a negative zero: "0.4", "-1", "0.258819". */
    private static String num(double value) {
        BigDecimal rounded = BigDecimal.valueOf(value).setScale(6, RoundingMode.HALF_EVEN);
        if (rounded.signum() == 0) {
            return "0";
        }
        return rounded.stripTrailingZeros().toPlainString();
    }
}
