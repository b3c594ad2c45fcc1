package ray.surface;

import java.util.ArrayList;
import java.util.List;
import ray.math.Vec3;

/**
 * An axis-aligned box from {@code minPt} to {@code maxPt}, made of 12 triangles wound so that
 * each face's geometric normal is its outward axis.
 */
public class Box extends TriangleSet {
    private Vec3 minPt = Vec3.ZERO;
    private Vec3 maxPt = Vec3.ONE;

    public void setMinPt(Vec3 minPt) {
        this.minPt = minPt;
    }

    public void setMaxPt(Vec3 maxPt) {
        this.maxPt = maxPt;
    }

    public Vec3 getMinPt() {
        return minPt;
    }

    public Vec3 getMaxPt() {
        return maxPt;
    }

    @Override
    public Surface complete() {
        if (!(minPt.x < maxPt.x && minPt.y < maxPt.y && minPt.z < maxPt.z)) {
            throw new IllegalArgumentException("minPt " + minPt + " is not below maxPt " + maxPt
                    + " on every axis; expected minPt < maxPt in x, y and z");
        }
        List<Triangle> built = new ArrayList<>();
        // Corner k has x from bit 0, y from bit 1, z from bit 2 (0 = min, 1 = max).
        Vec3[] c = new Vec3[8];
        for (int k = 0; k < 8; k++) {
            c[k] = new Vec3((k & 1) == 0 ? minPt.x : maxPt.x, (k & 2) == 0 ? minPt.y : maxPt.y, (k & 4) == 0 ? minPt.z : maxPt.z);
        }
        // Each face as a quad a, b, c, d counter-clockwise seen from outside.
        int[][] faces = {
            {0, 4, 6, 2}, // −x
            {1, 3, 7, 5}, // +x
            {0, 1, 5, 4}, // −y
            {2, 6, 7, 3}, // +y
            {0, 2, 3, 1}, // −z
            {4, 5, 7, 6}, // +z
        };
        for (int[] f : faces) {
            built.add(new Triangle(c[f[0]], c[f[1]], c[f[2]]));
            built.add(new Triangle(c[f[0]], c[f[2]], c[f[3]]));
        }
        setTriangles(built);
        return this;
    }

    @Override
    public Surface inFrameAt(Vec3 origin) {
        Vec3 min = minPt.minus(origin);
        Vec3 max = maxPt.minus(origin);
        if (!(min.x < max.x && min.y < max.y && min.z < max.z)) {
            // Thinner than a double can tell apart at the camera's distance: keep it as it is, placed.
            return super.inFrameAt(origin);
        }
        Box moved = new Box();
        moved.setMinPt(min);
        moved.setMaxPt(max);
        moved.setShader(getShader());
        return moved.complete();
    }

    @Override
    public String toString() {
        return "Box[" + minPt + " to " + maxPt + "]";
    }
}
