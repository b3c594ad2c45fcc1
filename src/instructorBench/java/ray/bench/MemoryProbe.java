package ray.bench;

import com.google.gson.Gson;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.lang.ref.Reference;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.LinkedHashMap;
import java.util.Map;
import ray.render.Renderer;
import ray.scene.ObjReader;
import ray.scene.Scene;
import ray.scene.SceneLoader;
import ray.surface.Mesh;
import ray.surface.MeshData;

/**
 * Memory figures, each measured in a fresh JVM that {@link BenchMain} starts (so one probe's
 * garbage never counts in another's), printing one JSON line:
 * <ul>
 * <li>{@code scene FILE}: the live heap the loaded scene holds (used heap after a full GC, minus
 * the same before loading), and the peak heap while loading and rendering it on every core
 * (sum of the heap pools' peak use; depends on the collector, which BenchMain fixes);</li>
 * <li>{@code mesh FOLDER}: load time of the generated 1M-triangle OBJ (read plus building the
 * triangles; the first load in the JVM, cold, and the best of three) and the bytes each triangle
 * keeps live, split into the flat arrays of {@link MeshData} and the Triangle objects.</li>
 * </ul>
 */
public final class MemoryProbe {
    public static void main(String[] args) throws Exception {
        Map<String, Object> result = args[0].equals("scene") ? scene(Paths.get(args[1])) : mesh(Paths.get(args[1]));
        System.out.println(new Gson().toJson(result));
    }

    private static Map<String, Object> scene(Path file) {
        long before = liveHeap();
        resetPeaks();
        Scene scene = SceneLoader.load(file);
        long live = liveHeap() - before;
        resetPeaks();
        new Renderer(scene, 0, 0).render();
        Map<String, Object> r = new LinkedHashMap<>();
        r.put("scene", file.toString());
        r.put("liveBytes", live);
        r.put("peakHeapBytes", peakHeap());
        Reference.reachabilityFence(scene);
        return r;
    }

    private static Map<String, Object> mesh(Path folder) throws Exception {
        Path obj = LargeMesh.file(folder);
        double cold = 0;
        double best = Double.POSITIVE_INFINITY;
        long live = 0;
        long arrays = 0;
        int triangles = 0;
        for (int run = 0; run < 3; run++) {
            long before = liveHeap();
            long start = System.nanoTime();
            MeshData data = ObjReader.read(obj);
            Mesh mesh = new Mesh();
            mesh.setData(data);
            mesh.complete();
            double seconds = (System.nanoTime() - start) / 1e9;
            cold = run == 0 ? seconds : cold;
            best = Math.min(best, seconds);
            if (run == 0) {
                live = liveHeap() - before; // later runs could see the earlier mesh freed meanwhile
            }
            triangles = data.triangleCount();
            arrays = 8L * data.positions.length + 4L * data.triangles.length
                    + (data.normals == null ? 0 : 8L * data.normals.length)
                    + (data.triangleNormals == null ? 0 : 4L * data.triangleNormals.length);
            Reference.reachabilityFence(mesh);
        }
        Map<String, Object> r = new LinkedHashMap<>();
        r.put("file", obj.toString());
        r.put("triangles", triangles);
        r.put("coldLoadSeconds", cold);
        r.put("bestLoadSeconds", best);
        r.put("bytesPerTriangle", (double) live / triangles);
        r.put("arrayBytesPerTriangle", (double) arrays / triangles);
        return r;
    }

    private static long liveHeap() {
        for (int k = 0; k < 3; k++) {
            System.gc();
        }
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
    }

    private static void resetPeaks() {
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            pool.resetPeakUsage();
        }
    }

    private static long peakHeap() {
        long sum = 0;
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP) {
                sum += pool.getPeakUsage().getUsed();
            }
        }
        return sum;
    }
}
