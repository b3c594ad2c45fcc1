package ray.numerics;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import ray.math.Vec3;
import ray.tools.Icosphere;
import ray.surface.Mesh;
import ray.surface.MeshData;

/**
 * A closed triangle mesh with shared vertex indices, as an OBJ file would give it: an icosahedron
 * subdivided once (42 vertices, 120 edges, 80 triangles), pushed out onto a sphere and placed at
 * any center. Every edge is shared by exactly two triangles that walk it in opposite directions,
 * and every vertex by five or six, so a ray from inside aimed at an edge or a vertex finds the
 * mesh's seams. Wound counter-clockwise seen from outside.
 */
final class ClosedMesh {
    private ClosedMesh() {
    }

    /** An icosphere subdivided once ({@link Icosphere}: 80 triangles sharing 42 vertices) of {@code radius} around {@code center}. */
    static MeshData data(Vec3 center, double radius) {
        return Icosphere.of(1, center, radius);
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
}
