package ray.numerics;

import java.util.function.LongFunction;
import java.util.stream.IntStream;
import ray.IntersectionRecord;

/**
 * The long sweep behind the sphere figures of docs/numerics.md: textbook vs robust sphere against
 * the exact (BigDecimal) answer for the same double inputs, about 1e6 seeded rays per row.
 *
 * <p>Tables: (1) far unit spheres, rays within ±0.1% of the silhouette (the catalogue's case, as in
 * FarSphereSilhouetteTest); (2) the same with impact parameters over [0, 2r] (most rays far from the
 * silhouette: the spread behind the figures quoted in REFERENCES.md); (3) rays starting 1 unit above
 * huge spheres (HugeSphereNearRootTest's cases). "wrong" is hit/miss disagreement with the exact
 * classification; "rel t err" is |t − t*|/t* over rays both call a hit; "err/κ" divides |t − t*| by
 * ExactSphere.conditionBound, how far t* moves when every input moves by a relative 2⁻⁵².
 *
 * <p>Run (from the project root, after compiling main and instructorTest):
 * {@code java -cp build/classes/java/main:build/classes/java/test ray.numerics.SphereSweep [raysPerRow]}.
 * Rows are split into seeded chunks of 10,000 rays run in parallel, so the figures do not depend on
 * the number of threads.
 */
public final class SphereSweep {
    private static final int CHUNK = 10_000;

    private SphereSweep() {
    }

    public static void main(String[] args) {
        int raysPerRow = args.length > 0 ? Integer.parseInt(args[0]) : 1_000_000;
        long started = System.nanoTime();
        silhouetteTable("Unit sphere at distance D, impact parameter within ±0.1% of r", SilhouetteRays.NEAR_SILHOUETTE, raysPerRow);
        silhouetteTable("Unit sphere at distance D, impact parameter uniform in [0, 2r]", SilhouetteRays.WHOLE_DISK, raysPerRow);
        hugeSphereTable(raysPerRow / 10);
        System.out.printf("%n(%d rays per silhouette row, %.0f s)%n", raysPerRow, (System.nanoTime() - started) / 1e9);
    }

    private static void silhouetteTable(String title, double spread, int raysPerRow) {
        System.out.printf("%n%s%n%n", title);
        System.out.println("| D | rays | textbook wrong | robust wrong | rays within ε·D·r of tangency | textbook max rel t err | robust max rel t err | textbook max err/κ | robust max err/κ |");
        System.out.println("| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
        for (int e = 2; e <= 8; e++) {
            double distance = Math.pow(10, e);
            long rowSeed = 1_000_000L * e + (spread == SilhouetteRays.NEAR_SILHOUETTE ? 0 : 500_000);
            Tally t = run(raysPerRow, seed -> new SilhouetteRays(seed, distance, spread)::next, rowSeed);
            System.out.printf("| 1e%d | %d | %s | %s | %d | %.2g | %.2g | %.2g | %.2g |%n", e, t.rays, percent(t.textbookWrong, t.rays),
                percent(t.robustWrong, t.rays), t.nearTangent, t.textbookRelative, t.robustRelative, t.textbookKappa, t.robustKappa);
        }
    }

    private static void hugeSphereTable(int raysPerRow) {
        System.out.printf("%nRay starting 0.5–1.5 above a sphere of radius R, heading in (near root)%n%n");
        System.out.println("| placement | R | rays | robust wrong | textbook max ulps of t | robust max ulps of t | textbook max err/κ | robust max err/κ |");
        System.out.println("| --- | --- | --- | --- | --- | --- | --- | --- |");
        for (int ground = 1; ground >= 0; ground--) {
            for (int e = 3; e <= 6; e++) {
                double radius = Math.pow(10, e);
                boolean onGround = ground == 1;
                LongFunction<Generator> generators = seed -> (onGround ? HugeSphereRays.ground(seed, radius) : HugeSphereRays.anywhere(seed, radius))::next;
                Tally t = run(raysPerRow, generators, 7_000_000L * e + ground * 100_000);
                System.out.printf("| %s | 1e%d | %d | %d | %.3g | %.3g | %.2g | %.2g |%n", onGround ? "ground, exact f·f" : "anywhere", e, t.rays,
                    t.robustWrong, t.textbookUlps, t.robustUlps, t.textbookKappa, t.robustKappa);
            }
        }
    }

    /** Runs one row: chunks of CHUNK rays, chunk i seeded rowSeed + i, merged in any order. */
    private static Tally run(int rays, LongFunction<Generator> generators, long rowSeed) {
        int chunks = (rays + CHUNK - 1) / CHUNK;
        return IntStream.range(0, chunks).parallel()
            .mapToObj(i -> chunk(generators.apply(rowSeed + i), Math.min(CHUNK, rays - i * CHUNK)))
            .reduce(new Tally(), Tally::merge);
    }

    private static Tally chunk(Generator generator, int rays) {
        Tally t = new Tally();
        for (int i = 0; i < rays; i++) {
            SphereCase k = generator.next();
            IntersectionRecord robust = new IntersectionRecord();
            IntersectionRecord textbook = new IntersectionRecord();
            boolean robustHit = k.robust().intersect(robust, k.ray);
            boolean textbookHit = k.textbook().intersect(textbook, k.ray);
            ExactSphere exact = k.exact();
            t.rays++;
            t.robustWrong += robustHit != exact.hit ? 1 : 0;
            t.textbookWrong += textbookHit != exact.hit ? 1 : 0;
            t.nearTangent += Math.abs(exact.tangencyMargin()) < 1 ? 1 : 0;
            if (!exact.hit) {
                continue;
            }
            double kappa = exact.conditionBound(k.ray, k.center);
            if (robustHit) {
                t.robustRelative = Math.max(t.robustRelative, exact.relativeError(robust.t));
                t.robustUlps = Math.max(t.robustUlps, exact.ulpsOff(robust.t));
                t.robustKappa = Math.max(t.robustKappa, exact.absoluteError(robust.t) / kappa);
            }
            if (textbookHit) {
                t.textbookRelative = Math.max(t.textbookRelative, exact.relativeError(textbook.t));
                t.textbookUlps = Math.max(t.textbookUlps, exact.ulpsOff(textbook.t));
                t.textbookKappa = Math.max(t.textbookKappa, exact.absoluteError(textbook.t) / kappa);
            }
        }
        return t;
    }

    private static String percent(long count, long of) {
        return String.format("%.4g%% (%d)", 100.0 * count / of, count);
    }

    /** A seeded source of cases. */
    private interface Generator {
        SphereCase next();
    }

    /** Counts and maxima of one row; merging is order-independent. */
    private static final class Tally {
        long rays;
        long robustWrong;
        long textbookWrong;
        long nearTangent;
        double robustRelative;
        double textbookRelative;
        double robustUlps;
        double textbookUlps;
        double robustKappa;
        double textbookKappa;

        Tally merge(Tally o) {
            Tally m = new Tally();
            m.rays = rays + o.rays;
            m.robustWrong = robustWrong + o.robustWrong;
            m.textbookWrong = textbookWrong + o.textbookWrong;
            m.nearTangent = nearTangent + o.nearTangent;
            m.robustRelative = Math.max(robustRelative, o.robustRelative);
            m.textbookRelative = Math.max(textbookRelative, o.textbookRelative);
            m.robustUlps = Math.max(robustUlps, o.robustUlps);
            m.textbookUlps = Math.max(textbookUlps, o.textbookUlps);
            m.robustKappa = Math.max(robustKappa, o.robustKappa);
            m.textbookKappa = Math.max(textbookKappa, o.textbookKappa);
            return m;
        }
    }
}
