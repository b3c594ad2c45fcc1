package ray.numerics;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import ray.math.Vec3;
import ray.surface.Mesh;
import ray.surface.MeshData;

/**
 * A closed triangle mesh with shared vertex indices, as an OBJ file would give it: an icosahedron
 * subdivided once (42 vertices, 120 edges, 80 triangles), pushed out onto a sphere and placed at
 * any center. Every edge is shared by exactly two triangles that walk it in opposite directions,
 * and every vertex by five or six, so a ray from inside aimed at an edge or a vertex finds the
 * mesh's seams. Wound counter-clockwise seen from outside.
 */
final class Icosphere {
    private static final double PHI = (1 + Math.sqrt(5)) / 2;
    private static final double[][] ICOSAHEDRON = {
        {-1, PHI, 0}, {1, PHI, 0}, {-1, -PHI, 0}, {1, -PHI, 0},
        {0, -1, PHI}, {0, 1, PHI}, {0, -1, -PHI}, {0, 1, -PHI},
        {PHI, 0, -1}, {PHI, 0, 1}, {-PHI, 0, -1}, {-PHI, 0, 1},
    };
    private static final int[] FACES = {
        0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11,
        1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
        3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9,
        4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1,
    };

    private Icosphere() {
    }

    /** The mesh data: unit directions from the icosahedron, each vertex at center + radius·direction. */
    static MeshData data(Vec3 center, double radius) {
        List<Vec3> directions = new ArrayList<>();
        for (double[] v : ICOSAHEDRON) {
            directions.add(new Vec3(v[0], v[1], v[2]).normalized());
        }
        // Split each triangle into four at its edge midpoints; a map keeps one midpoint per edge.
        Map<Long, Integer> midpoints = new HashMap<>();
        int[] faces = new int[FACES.length * 4];
        for (int f = 0; f < FACES.length; f += 3) {
            int a = FACES[f];
            int b = FACES[f + 1];
            int c = FACES[f + 2];
            int ab = midpoint(a, b, directions, midpoints);
            int bc = midpoint(b, c, directions, midpoints);
            int ca = midpoint(c, a, directions, midpoints);
            int[] four = {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca};
            System.arraycopy(four, 0, faces, f * 4, 12);
        }
        double[] positions = new double[3 * directions.size()];
        for (int i = 0; i < directions.size(); i++) {
            Vec3 p = center.plus(directions.get(i).times(radius));
            positions[3 * i] = p.x;
            positions[3 * i + 1] = p.y;
            positions[3 * i + 2] = p.z;
        }
        return new MeshData(positions, null, faces, null);
    }

    /** The completed Mesh of {@link #data}, its triangles sharing their vertex objects. */
    static Mesh mesh(MeshData data) {
        Mesh mesh = new Mesh();
        mesh.setData(data);
        mesh.complete();
        return mesh;
    }

    /** Every edge once, as pairs of vertex indices (i &lt; j). */
    static List<int[]> edges(MeshData data) {
        Map<Long, int[]> edges = new LinkedHashMap<>();
        int[] tri = data.triangles;
        for (int k = 0; k < tri.length; k += 3) {
            for (int e = 0; e < 3; e++) {
                int i = Math.min(tri[k + e], tri[k + (e + 1) % 3]);
                int j = Math.max(tri[k + e], tri[k + (e + 1) % 3]);
                edges.putIfAbsent((long) i << 32 | j, new int[] {i, j});
            }
        }
        return new ArrayList<>(edges.values());
    }

    private static int midpoint(int a, int b, List<Vec3> directions, Map<Long, Integer> midpoints) {
        long key = (long) Math.min(a, b) << 32 | Math.max(a, b);
        return midpoints.computeIfAbsent(key, k -> {
            directions.add(directions.get(a).plus(directions.get(b)).normalized());
            return directions.size() - 1;
        });
    }
}
