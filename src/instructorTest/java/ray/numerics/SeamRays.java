package ray.numerics;

import java.util.List;
import java.util.Random;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.MeshData;

/**
 * Seeded rays from inside a closed mesh aimed exactly at its seams: a quarter at a vertex itself,
 * the rest at an edge point v_i + s·(v_j − v_i), s uniform in [0, 1], computed in double (so the
 * target is the edge point rounded, a hair to one side or the other). Origins are uniform in the
 * ball of radius 0.5·radius around the mesh's center. A ray from inside a closed mesh must hit it.
 */
final class SeamRays {
    private final Random random;
    private final Vec3[] vertices;
    private final List<int[]> edges;
    private final Vec3 center;
    private final double radius;
    /** Whether the last ray was aimed at a vertex (else at an edge point). */
    boolean atVertex;

    SeamRays(long seed, MeshData mesh, Vec3 center, double radius) {
        this.random = new Random(seed);
        this.vertices = new Vec3[mesh.vertexCount()];
        for (int i = 0; i < vertices.length; i++) {
            vertices[i] = new Vec3(mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]);
        }
        this.edges = ClosedMesh.edges(mesh);
        this.center = center;
        this.radius = radius;
    }

    Ray next() {
        Vec3 target;
        atVertex = random.nextInt(4) == 0;
        if (atVertex) {
            target = vertices[random.nextInt(vertices.length)];
        } else {
            int[] edge = edges.get(random.nextInt(edges.size()));
            Vec3 a = vertices[edge[0]];
            Vec3 b = vertices[edge[1]];
            target = a.plus(b.minus(a).times(random.nextDouble()));
        }
        Vec3 origin = center.plus(insideUnitBall().times(0.5 * radius));
        return new Ray(origin, target.minus(origin));
    }

    private Vec3 insideUnitBall() {
        while (true) {
            Vec3 p = new Vec3(2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1);
            if (p.lengthSquared() <= 1) {
                return p;
            }
        }
    }
}
