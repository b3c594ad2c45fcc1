package ray.tools;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import ray.math.Vec3;
import ray.surface.MeshData;

/**
 * A sphere made of triangles: an icosahedron whose faces are split into four at their edge
 * midpoints, pushed out onto the sphere, {@code subdivisions} times (20·4^k triangles). It is a
 * closed mesh: every edge is shared by exactly two triangles that use the same vertex indices and
 * walk it in opposite directions. Faces are counter-clockwise seen from outside.
 */
public final class Icosphere {
    private static final double PHI = (1 + Math.sqrt(5)) / 2;
    /** The icosahedron's corners (0, ±1, ±φ), (±1, ±φ, 0), (±φ, 0, ±1), before normalizing. */
    private static final double[][] CORNERS = {
        {-1, PHI, 0}, {1, PHI, 0}, {-1, -PHI, 0}, {1, -PHI, 0},
        {0, -1, PHI}, {0, 1, PHI}, {0, -1, -PHI}, {0, 1, -PHI},
        {PHI, 0, -1}, {PHI, 0, 1}, {-PHI, 0, -1}, {-PHI, 0, 1},
    };
    /** Its 20 faces, counter-clockwise seen from outside. */
    private static final int[] FACES = {
        0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11,
        1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
        3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9,
        4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1,
    };

    private Icosphere() {
    }

    /** The mesh data of an icosphere of {@code radius} around {@code center}, with no vertex normals. */
    public static MeshData of(int subdivisions, Vec3 center, double radius) {
        if (subdivisions < 0) {
            throw new IllegalArgumentException("subdivisions must be ≥ 0, got " + subdivisions);
        }
        List<Vec3> directions = new ArrayList<>();
        for (double[] c : CORNERS) {
            directions.add(new Vec3(c[0], c[1], c[2]).normalized());
        }
        int[] faces = FACES;
        for (int level = 0; level < subdivisions; level++) {
            // A map keeps one midpoint per edge, so that the two faces on an edge share it by index.
            Map<Long, Integer> midpoints = new HashMap<>();
            int[] finer = new int[4 * faces.length];
            for (int f = 0; f < faces.length; f += 3) {
                int a = faces[f];
                int b = faces[f + 1];
                int c = faces[f + 2];
                int ab = midpoint(a, b, directions, midpoints);
                int bc = midpoint(b, c, directions, midpoints);
                int ca = midpoint(c, a, directions, midpoints);
                int[] four = {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca};
                System.arraycopy(four, 0, finer, 4 * f, 12);
            }
            faces = finer;
        }
        double[] positions = new double[3 * directions.size()];
        for (int i = 0; i < directions.size(); i++) {
            Vec3 p = center.plus(directions.get(i).times(radius));
            positions[3 * i] = p.x;
            positions[3 * i + 1] = p.y;
            positions[3 * i + 2] = p.z;
        }
        return new MeshData(positions, null, faces.clone(), null);
    }

    /** The index of the unit midpoint of edge ab, made once for both faces that share the edge. */
    private static int midpoint(int a, int b, List<Vec3> directions, Map<Long, Integer> midpoints) {
        long key = (long) Math.min(a, b) << 32 | Math.max(a, b);
        return midpoints.computeIfAbsent(key, k -> {
            directions.add(directions.get(a).plus(directions.get(b)).normalized());
            return directions.size() - 1;
        });
    }
}
