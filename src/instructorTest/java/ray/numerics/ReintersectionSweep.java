package ray.numerics;

import java.util.List;
import ray.numerics.Reintersection.Kind;
import ray.numerics.Reintersection.Spawner;
import ray.numerics.Reintersection.Tally;
import ray.render.SecondaryRays;

/**
 * Prints the re-hit rates of the catalogue in {@link Reintersection} (shadow acne) for several ways
 * of starting new rays, as markdown tables for docs/numerics.md:
 * <ol>
 * <li>with the solution's intersection code: no offset (t_min = 0), fixed t_min of 1e-6 and 1e-3,
 *     the renderer's rule before issue 4 (1e-9·(1 + max|p_i|) along the shading normal), and the
 *     renderer's offset ({@link SecondaryRays});</li>
 * <li>the renderer's offset with other multiples of ε·scale, to show the margin on both sides: too
 *     small re-hits, too large jumps over small objects far from the origin;</li>
 * <li>with textbook intersection code (a student's first sphere and Cramer's-rule triangle), and
 *     the margin the renderer's offset needs there.</li>
 * </ol>
 * Usage: {@code ReintersectionSweep [SURFACES [RAYS-PER-HIT]]} (default 20000 surfaces per case,
 * 25 leaving and 25 shadow rays from each hit: about 10^6 rays per cell; a few minutes in all).
 */
public final class ReintersectionSweep {
    private ReintersectionSweep() {
    }

    public static void main(String[] args) {
        int surfaces = args.length > 0 ? Integer.parseInt(args[0]) : 20000;
        int raysPerHit = args.length > 1 ? Integer.parseInt(args[1]) : 25;
        System.out.printf("Re-hit rates, %d surfaces per case, %d leaving + %d shadow rays from each hit (seed 2024).%n%n",
                surfaces, raysPerHit, raysPerHit);
        System.out.println("Solution's intersection code:\n");
        table(List.of(Reintersection.NO_OFFSET, Reintersection.fixedStart(1e-6), Reintersection.fixedStart(1e-3),
                Reintersection.RELATIVE_1E9, Reintersection.FRAMEWORK, Reintersection.ERROR_BOUND), false, surfaces, raysPerHit);
        System.out.println("\nThe renderer's offset with other multiples K of eps*scale (the renderer uses "
                + (long) SecondaryRays.OFFSET_ULPS + "):\n");
        table(List.of(Reintersection.geometryOffset(1), Reintersection.geometryOffset(2), Reintersection.geometryOffset(4),
                Reintersection.geometryOffset(16), Reintersection.FRAMEWORK, Reintersection.geometryOffset(1 << 20),
                Reintersection.geometryOffset(1 << 24)), false, surfaces, raysPerHit);
        System.out.println("\nTextbook intersection code (quadratic sphere without re-projection, Cramer's-rule triangle):\n");
        table(List.of(Reintersection.NO_OFFSET, Reintersection.fixedStart(1e-6), Reintersection.RELATIVE_1E9, Reintersection.FRAMEWORK,
                Reintersection.ERROR_BOUND, Reintersection.errorBound(16), Reintersection.errorBound(64)), true, surfaces, raysPerHit);
        System.out.println("\nFar from the origin: sizes 10^U(0, 3) at 10^U(11.5, 12.5) from it (solution's code):\n");
        StringBuilder header = new StringBuilder("| case |");
        List<Spawner> far = List.of(Reintersection.NO_OFFSET, Reintersection.fixedStart(1e-6), Reintersection.fixedStart(1e-3),
                Reintersection.RELATIVE_1E9, Reintersection.FRAMEWORK);
        for (Spawner s : far) {
            header.append(' ').append(s).append(" |");
        }
        System.out.println(header);
        System.out.println("| --- |" + " ---: |".repeat(far.size()));
        for (Kind kind : new Kind[] {Kind.SPHERE, Kind.TRIANGLE, Kind.CLOSED_MESH}) {
            StringBuilder row = new StringBuilder("| ").append(kind.name().toLowerCase().replace('_', ' ')).append(" |");
            for (Spawner s : far) {
                Tally t = Reintersection.run(kind, s, false, 2024, surfaces / 4, raysPerHit, new double[] {0, 3}, new double[] {11.5, 12.5});
                row.append(cell(t));
            }
            System.out.println(row);
        }
        System.out.println("\nTextbook intersection code, the renderer's offset with other multiples K of eps*scale:\n");
        table(List.of(Reintersection.geometryOffset(4), Reintersection.geometryOffset(16), Reintersection.geometryOffset(64),
                Reintersection.geometryOffset(256)), true, surfaces, raysPerHit);
    }

    private static String cell(Tally t) {
        return (t.rehits() == 0 ? " 0" : String.format(" %.3g%%", 100 * t.rate())) + String.format(" (%d/%d) |", t.rehits(), t.rays());
    }

    private static void table(List<Spawner> spawners, boolean textbook, int surfaces, int raysPerHit) {
        StringBuilder header = new StringBuilder("| case |");
        StringBuilder rule = new StringBuilder("| --- |");
        for (Spawner s : spawners) {
            header.append(' ').append(s).append(" |");
            rule.append(" ---: |");
        }
        System.out.println(header);
        System.out.println(rule);
        for (Kind kind : Kind.values()) {
            StringBuilder row = new StringBuilder("| ").append(kind.name().toLowerCase().replace('_', ' ')).append(" |");
            for (Spawner s : spawners) {
                row.append(cell(Reintersection.run(kind, s, textbook, 2024, surfaces, raysPerHit)));
            }
            System.out.println(row);
        }
    }
}
