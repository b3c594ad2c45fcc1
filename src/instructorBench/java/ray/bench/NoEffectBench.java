package ray.bench;

import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import ray.IntersectionRecord;
import ray.camera.Camera;
import ray.image.Image;
import ray.math.Vec3;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneLoader;
import ray.surface.Surface;

/**
 * A scene that calls for no effect (the {@code normals} variant of {@link EffectScenes}: normals as
 * colors, no lights, one sample) rendered by the framework, against the bare loop a student could
 * write for it: one camera ray per pixel, the closest hit, its normal as the color. Both on one
 * thread. The ratio is what the framework's generality (the plan, the shader call, the counters,
 * the shading) costs a scene that uses none of it; setup checks that both make the same image.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class NoEffectBench {
    private Scene scene;

    @Setup
    public void setUp() throws Exception {
        Path folder = Paths.get("build", "bench", "scenes");
        EffectScenes.writeAll(folder);
        scene = SceneLoader.load(folder.resolve("normals.xml"));
        Image framework = framework();
        Image bare = bareLoop();
        for (int j = 0; j < scene.getHeight(); j++) {
            for (int i = 0; i < scene.getWidth(); i++) {
                if (!framework.get(i, j).equals(bare.get(i, j))) {
                    throw new IllegalStateException("the bare loop differs from the renderer at pixel " + i + ", " + j);
                }
            }
        }
    }

    @Benchmark
    public Image framework() {
        return new Renderer(scene, 0, 1).render().image;
    }

    @Benchmark
    public Image bareLoop() {
        Camera camera = scene.getCamera();
        Surface surfaces = scene.getSurfaces();
        Vec3 back = scene.getBackColor();
        int width = scene.getWidth();
        int height = scene.getHeight();
        Image image = new Image(width, height);
        for (int j = 0; j < height; j++) {
            for (int i = 0; i < width; i++) {
                IntersectionRecord hit = new IntersectionRecord();
                boolean found = surfaces.intersect(hit, camera.generateRay((i + 0.5) / width, (j + 0.5) / height));
                image.set(i, j, found ? hit.normal.plus(Vec3.ONE).times(0.5) : back);
            }
        }
        return image;
    }
}
