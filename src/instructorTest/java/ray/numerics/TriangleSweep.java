package ray.numerics;

import java.util.List;
import java.util.Random;
import java.util.function.IntFunction;
import java.util.stream.IntStream;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Mesh;
import ray.surface.MeshData;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * The long sweep behind the triangle figures of docs/numerics.md: textbook vs robust ray–triangle
 * tests on the hard cases, about 1e6 seeded rays per row, printed as markdown tables.
 *
 * <ol>
 * <li>Seams of a closed mesh ({@link ClosedMesh}, radius 1, at distance 1, 1e3, 1e6 from the origin),
 *     rays from inside aimed exactly at vertices and edge points ({@link SeamRays}): the share that
 *     hits no triangle (passes between them), as in ClosedMeshWatertightTest.</li>
 * <li>Tiny triangles ({@link TinyTriangleRays}) with rays aimed inside: the share missed, with unit
 *     directions and with d = target − origin, as in TinyTriangleTest.</li>
 * <li>Degenerate triangles ({@link DegenerateTriangles}) with rays aimed at them: the share reported
 *     as hits, and of those the ones with a bad record (NaN, infinity, or a normal not of unit length),
 *     as in DegenerateTriangleTest.</li>
 * <li>Rays exactly in the plane of integer triangles, through their interior: the share reported as
 *     hits, as in RayInOrParallelToPlaneTest.</li>
 * </ol>
 *
 * <p>Run (from the project root, after compiling main and instructorTest):
 * {@code java -cp build/classes/java/main:build/classes/java/test ray.numerics.TriangleSweep [raysPerRow]}.
 * Rows are split into seeded chunks of 10,000 rays run in parallel, so the figures do not depend on
 * the number of threads.
 */
public final class TriangleSweep {
    private static final int CHUNK = 10_000;
    private static final TextbookTriangles.Method[] METHODS = {
        TextbookTriangles.MOLLER_TRUMBORE, TextbookTriangles.CRAMER, TextbookTriangles.ROBUST};

    private TriangleSweep() {
    }

    public static void main(String[] args) {
        int raysPerRow = args.length > 0 ? Integer.parseInt(args[0]) : 1_000_000;
        long started = System.nanoTime();
        seamTable(raysPerRow);
        tinyTable(raysPerRow);
        degenerateTable(raysPerRow);
        inPlaneTable(raysPerRow);
        System.out.printf("%n(%d rays per row, %.0f s)%n", raysPerRow, (System.nanoTime() - started) / 1e9);
    }

    private static void seamTable(int rays) {
        System.out.printf("%nRays from inside a closed mesh (icosphere, 80 triangles, radius 1) aimed exactly at its seams"
                + " (1/4 at vertices, 3/4 at edge points): share that passes between the triangles%n%n");
        System.out.println("| distance from origin | rays | Möller–Trumbore | of the vertex rays | Cramer | of the vertex rays | robust (WBW) |");
        System.out.println("| --- | --- | --- | --- | --- | --- | --- |");
        for (int e : new int[] {0, 3, 6}) {
            double distance = Math.pow(10, e);
            Vec3 center = new Vec3(0.6, -0.48, 0.64).times(distance);
            MeshData data = ClosedMesh.data(center, 1);
            Mesh mesh = ClosedMesh.mesh(data);
            List<Surface> triangles = mesh.children();
            // counts: rays, vertex rays, then per method leaks and vertex leaks.
            long[] c = sum(rays, 2 + 2 * METHODS.length, (chunk, n, counts) -> {
                SeamRays generator = new SeamRays(10_000_000L * e + chunk, data, center, 1);
                for (int i = 0; i < n; i++) {
                    Ray ray = generator.next();
                    counts[0]++;
                    counts[1] += generator.atVertex ? 1 : 0;
                    for (int m = 0; m < METHODS.length; m++) {
                        boolean hit = m == 2 ? mesh.intersect(new IntersectionRecord(), ray)
                                : ClosedMeshWatertightTest.anyHit(METHODS[m], triangles, ray);
                        counts[2 + 2 * m] += hit ? 0 : 1;
                        counts[3 + 2 * m] += hit || !generator.atVertex ? 0 : 1;
                    }
                }
            });
            System.out.printf("| %s | %d | %s | %s | %s | %s | %s |%n", e == 0 ? "1" : "1e" + e, c[0], percent(c[2], c[0]), percent(c[3], c[1]),
                    percent(c[4], c[0]), percent(c[5], c[1]), percent(c[6], c[0]));
        }
    }

    private static void tinyTable(int rays) {
        System.out.printf("%nTiny triangles seen from 0.5–2 sizes away, rays aimed inside: share missed%n%n");
        System.out.println("| size | rays | MT, abs(det) < 1e-8, unit d | MT, abs(det) < 1e-8, d = target − origin | Möller–Trumbore | Cramer | robust (WBW) |");
        System.out.println("| --- | --- | --- | --- | --- | --- | --- |");
        for (int e = 3; e <= 6; e++) {
            double size = Math.pow(10, -e);
            int exponent = e;
            long[] c = sum(rays, 6, (chunk, n, counts) -> {
                TinyTriangleRays unit = new TinyTriangleRays(20_000_000L * exponent + chunk, size, true);
                TinyTriangleRays aim = new TinyTriangleRays(30_000_000L * exponent + chunk, size, false);
                for (int i = 0; i < n; i++) {
                    counts[0]++;
                    Ray u = unit.next();
                    Ray a = aim.next();
                    counts[1] += TextbookTriangles.MOLLER_TRUMBORE_EPSILON.intersect(unit.triangle, new IntersectionRecord(), u) ? 0 : 1;
                    counts[2] += TextbookTriangles.MOLLER_TRUMBORE_EPSILON.intersect(aim.triangle, new IntersectionRecord(), a) ? 0 : 1;
                    // The other three over both kinds of rays: two tests per ray.
                    for (int m = 0; m < METHODS.length; m++) {
                        counts[3 + m] += (METHODS[m].intersect(unit.triangle, new IntersectionRecord(), u) ? 0 : 1)
                                + (METHODS[m].intersect(aim.triangle, new IntersectionRecord(), a) ? 0 : 1);
                    }
                }
            });
            System.out.printf("| 1e-%d | %d | %s | %s | %s | %s | %s |%n", e, c[0], percent(c[1], c[0]), percent(c[2], c[0]),
                    percent(c[3], 2 * c[0]), percent(c[4], 2 * c[0]), percent(c[5], 2 * c[0]));
        }
    }

    private static void degenerateTable(int rays) {
        System.out.printf("%nDegenerate triangles, rays from random origins aimed at a point of them: share reported as a hit"
                + " (a false hit), and the share of all rays that hit with a bad record (NaN or infinity, or a normal not of unit length)%n%n");
        System.out.println("| kind | rays | Möller–Trumbore hits | of which bad | Cramer hits | of which bad | robust (WBW) hits | of which bad |");
        System.out.println("| --- | --- | --- | --- | --- | --- | --- | --- |");
        for (int kind = 0; kind < DegenerateTriangles.KINDS.length; kind++) {
            int k = kind;
            // counts: rays, then per method hits and non-finite hits.
            long[] c = sum(rays, 1 + 2 * METHODS.length, (chunk, n, counts) -> {
                DegenerateTriangles triangles = new DegenerateTriangles(40_000_000L * k + chunk);
                Random random = new Random(50_000_000L * k + chunk);
                for (int i = 0; i < n; i++) {
                    Triangle t = triangles.next(k);
                    Vec3 origin = new Vec3(400 * random.nextDouble() - 200, 400 * random.nextDouble() - 200, 400 * random.nextDouble() - 200);
                    Ray ray = new Ray(origin, triangles.target.minus(origin));
                    counts[0]++;
                    for (int m = 0; m < METHODS.length; m++) {
                        IntersectionRecord out = new IntersectionRecord();
                        if (METHODS[m].intersect(t, out, ray)) {
                            counts[1 + 2 * m]++;
                            counts[2 + 2 * m] += sound(out) ? 0 : 1;
                        }
                    }
                }
            });
            System.out.printf("| %s | %d | %s | %s | %s | %s | %s | %s |%n", DegenerateTriangles.KINDS[kind], c[0],
                    percent(c[1], c[0]), percent(c[2], c[0]), percent(c[3], c[0]), percent(c[4], c[0]), percent(c[5], c[0]), percent(c[6], c[0]));
        }
    }

    private static void inPlaneTable(int rays) {
        System.out.printf("%nRays exactly in the plane of integer triangles (coordinates up to 2^20), through their interior:"
                + " share reported as a hit%n%n");
        System.out.println("| rays | Möller–Trumbore | Cramer | robust (WBW) |");
        System.out.println("| --- | --- | --- | --- |");
        long[] c = sum(rays, 1 + METHODS.length, (chunk, n, counts) -> {
            Random random = new Random(60_000_000L + chunk);
            for (int i = 0; i < n; i++) {
                Vec3 v0 = integerPoint(random);
                Vec3 e1 = integerPoint(random).minus(v0);
                Vec3 e2 = integerPoint(random).minus(v0);
                Triangle t = new Triangle(v0, v0.plus(e1), v0.plus(e2));
                int alpha = 1 + random.nextInt(6);
                int beta = 1 + random.nextInt(7 - alpha);
                Vec3 inside = v0.plus(e1.times(alpha / 8.0)).plus(e2.times(beta / 8.0));
                Vec3 along = e1.times(random.nextInt(41) - 20).plus(e2.times(random.nextInt(41) - 20));
                if (DegenerateTriangles.hasNoArea(t) || along.lengthSquared() == 0) {
                    i--;
                    continue;
                }
                Ray ray = new Ray(inside.minus(along.times(7)), along);
                counts[0]++;
                for (int m = 0; m < METHODS.length; m++) {
                    counts[1 + m] += METHODS[m].intersect(t, new IntersectionRecord(), ray) ? 1 : 0;
                }
            }
        });
        System.out.printf("| %d | %s | %s | %s |%n", c[0], percent(c[1], c[0]), percent(c[2], c[0]), percent(c[3], c[0]));
    }

    /** One chunk of a row: n rays from the chunk's own seed, adding to counts. */
    private interface Chunk {
        void run(int chunk, int n, long[] counts);
    }

    /** Runs ⌈rays/CHUNK⌉ chunks in parallel and adds up their counts. */
    private static long[] sum(int rays, int width, Chunk chunk) {
        int chunks = (rays + CHUNK - 1) / CHUNK;
        IntFunction<long[]> one = i -> {
            long[] counts = new long[width];
            chunk.run(i, Math.min(CHUNK, rays - i * CHUNK), counts);
            return counts;
        };
        return IntStream.range(0, chunks).parallel().mapToObj(one).reduce(new long[width], (a, b) -> {
            long[] s = new long[width];
            for (int k = 0; k < width; k++) {
                s[k] = a[k] + b[k];
            }
            return s;
        });
    }

    /** A record without NaN or infinity, with a unit normal. */
    private static boolean sound(IntersectionRecord r) {
        return Double.isFinite(r.t) && r.location.isFinite() && r.normal.isFinite() && Double.isFinite(r.beta) && Double.isFinite(r.gamma)
                && Math.abs(r.normal.length() - 1) < 1e-9;
    }

    private static Vec3 integerPoint(Random random) {
        return new Vec3(random.nextInt(1 << 21) - (1 << 20), random.nextInt(1 << 21) - (1 << 20), random.nextInt(1 << 21) - (1 << 20));
    }

    private static String percent(long count, long of) {
        if (count == 0) {
            return "0";
        }
        double p = 100.0 * count / of;
        return (count == of ? "100%" : p >= 1 ? String.format("%.1f%%", p) : p >= 0.01 ? String.format("%.2f%%", p) : String.format("%.2g%%", p))
                + " (" + count + ")";
    }
}
