package ray.numerics;

import java.util.Locale;

/**
 * Runs every long numerics sweep in turn ({@code gradle numericsSweep}) and prints their tables:
 * the figures of docs/numerics.md. Each sweep is seeded, so a rerun prints the same numbers.
 * Takes about ten minutes on two cores; each sweep can also be run alone with its own main.
 */
public final class NumericsSweeps {
    private NumericsSweeps() {
    }

    public static void main(String[] args) {
        run("Spheres: hit/miss against an exact oracle, root accuracy", () -> SphereSweep.main(new String[0]));
        run("Triangles: cracks, tiny triangles, degenerate triangles", () -> TriangleSweep.main(new String[0]));
        run("Secondary rays: re-hits of the surface they leave", () -> ReintersectionSweep.main(new String[0]));
        run("Whole scenes moved by 1e5 or scaled by 1e-3", () -> SceneInvarianceSurvey.main(new String[0]));
    }

    private static void run(String title, Runnable sweep) {
        System.out.println("\n=== " + title + " ===\n");
        long start = System.nanoTime();
        sweep.run();
        System.out.printf(Locale.ROOT, "%n(%.0f s)%n", (System.nanoTime() - start) / 1e9);
    }
}
