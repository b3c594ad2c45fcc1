package ray.surface;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleFunction;
import ray.ShortPaths;
import ray.math.Vec3;

/**
 * A triangle mesh, usually read from an OBJ file. Its triangles share their vertex objects, and
 * use interpolated vertex normals and texture coordinates when the file gives them.
 */
public class Mesh extends TriangleSet {
    private MeshData data;

    public void setData(MeshData data) {
        this.data = data;
    }

    public MeshData getData() {
        return data;
    }

    @Override
    public Surface complete() {
        if (data == null) {
            throw new IllegalArgumentException("no <data> is given; expected <data> with the path of an OBJ file");
        }
        List<Triangle> built = new ArrayList<>(data.triangleCount());
        Vec3[] vertices = toVectors(data.positions);
        Vec3[] normals = data.triangleNormals == null ? null : toVectors(data.normals);
        Vec3[] texCoords = data.triangleTexCoords == null ? null : toUv(data.texCoords);
        int[] tri = data.triangles;
        for (int k = 0; k < tri.length; k += 3) {
            int[] tn = data.triangleNormals;
            Triangle triangle;
            // A face without normals (index -1) is flat even in a mesh whose other faces have them.
            if (normals == null || tn[k] < 0) {
                triangle = new Triangle(vertices[tri[k]], vertices[tri[k + 1]], vertices[tri[k + 2]]);
            } else {
                triangle = new Triangle(vertices[tri[k]], vertices[tri[k + 1]], vertices[tri[k + 2]],
                        normals[tn[k]], normals[tn[k + 1]], normals[tn[k + 2]]);
            }
            int[] tt = data.triangleTexCoords;
            // Likewise a face without texture coordinates keeps (0, 0) at every corner.
            if (texCoords != null && tt[k] >= 0) {
                triangle.setVt0(texCoords[tt[k]]);
                triangle.setVt1(texCoords[tt[k + 1]]);
                triangle.setVt2(texCoords[tt[k + 2]]);
            }
            built.add(triangle);
        }
        setTriangles(built);
        return this;
    }

    /** The same mesh with every vertex position moved, built anew (its tree included) as a loaded mesh is. */
    @Override
    public Surface inFrameAt(Vec3 origin) {
        Mesh moved = new Mesh();
        moved.setData(data.inFrameAt(origin));
        moved.setShader(getShader());
        return moved.complete();
    }

    /** (u, v) pairs as vectors (u, v, 0). */
    private static Vec3[] toUv(double[] uv) {
        Vec3[] t = new Vec3[uv.length / 2];
        for (int i = 0; i < t.length; i++) {
            t[i] = new Vec3(uv[2 * i], uv[2 * i + 1], 0);
        }
        return t;
    }

    private static Vec3[] toVectors(double[] xyz) {
        Vec3[] v = new Vec3[xyz.length / 3];
        for (int i = 0; i < v.length; i++) {
            v[i] = new Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        }
        return v;
    }

    @Override
    public String describe(DoubleFunction<String> number) {
        Path file = getData() == null ? null : getData().source;
        return "Mesh " + (file != null ? ShortPaths.of(file) + " " : "") + "(" + ShapeFacts.count(children().size(), "triangle") + ")";
    }
}
