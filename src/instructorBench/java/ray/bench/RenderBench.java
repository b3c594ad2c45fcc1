package ray.bench;

import java.nio.file.Paths;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneLoader;

/**
 * The time of one whole render (the pixel loop, not loading or writing the PNG) per scene and
 * thread count. {@link BenchMain} passes every shipped scene, the hard-case scenes and the effect
 * variants of {@link EffectScenes} as {@code scene}, and threads 1 and 2; rays per second come from
 * dividing the scene's ray count (fixed by the scene) by this time.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 3, time = 1)
@Fork(2) // the JIT's choices vary from JVM to JVM: one fork's render time can be 15-25% off another's
public class RenderBench {
    /** A scene file, relative to the project folder. */
    @Param({"scenes/one-sphere.xml"})
    public String scene;

    @Param({"1", "2"})
    public int threads;

    private Scene loaded;

    @Setup
    public void setUp() {
        loaded = SceneLoader.load(Paths.get(scene));
    }

    @Benchmark
    public RenderResult render() {
        return new Renderer(loaded, 0, threads).render();
    }
}
