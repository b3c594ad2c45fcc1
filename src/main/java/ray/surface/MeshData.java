package ray.surface;

import java.nio.file.Path;

/**
 * Triangle-mesh data in flat arrays, as a file reader produces it: positions (x, y, z per vertex),
 * optional normals and texture coordinates, and three vertex indices per triangle (with three
 * normal indices when the faces carry normals, and three texture-coordinate indices when they
 * carry those).
 */
public final class MeshData {
    /** The file the mesh was read from, or null for a mesh made in code. */
    public final Path source;
    public final double[] positions;
    public final double[] normals;
    public final int[] triangles;
    /** Normal indices per triangle corner, or null when the faces carry no normals. */
    public final int[] triangleNormals;
    /** Texture coordinates (u, v per {@code vt} line). */
    public final double[] texCoords;
    /**
     * Texture-coordinate indices per triangle corner (−1 for a corner without one), or null when no
     * face carries them.
     */
    public final int[] triangleTexCoords;

    public MeshData(double[] positions, double[] normals, int[] triangles, int[] triangleNormals) {
        this(null, positions, normals, triangles, triangleNormals, new double[0], null);
    }

    public MeshData(Path source, double[] positions, double[] normals, int[] triangles, int[] triangleNormals,
            double[] texCoords, int[] triangleTexCoords) {
        this.source = source;
        this.positions = positions;
        this.normals = normals;
        this.triangles = triangles;
        this.triangleNormals = triangleNormals;
        this.texCoords = texCoords;
        this.triangleTexCoords = triangleTexCoords;
    }

    /** The same mesh with every position moved by −origin (normals, texture coordinates and faces shared). */
    public MeshData inFrameAt(ray.math.Vec3 origin) {
        double[] moved = new double[positions.length];
        for (int i = 0; i < positions.length; i += 3) {
            moved[i] = positions[i] - origin.x;
            moved[i + 1] = positions[i + 1] - origin.y;
            moved[i + 2] = positions[i + 2] - origin.z;
        }
        return new MeshData(source, moved, normals, triangles, triangleNormals, texCoords, triangleTexCoords);
    }

    public int vertexCount() {
        return positions.length / 3;
    }

    public int triangleCount() {
        return triangles.length / 3;
    }
}
