package ray.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import ray.IntersectionRecord;
import ray.Ray;
import ray.surface.Group;
import ray.surface.Surface;

/**
 * Ray–primitive tests per second on one core, three ways, each reported as time per single test:
 * <ul>
 * <li>{@code eachTest}: ray k against primitive k, one call per pair, no closest-hit bookkeeping
 * (the cost of the student's intersect method itself);</li>
 * <li>{@code group}: one ray against all {@value PrimitiveCloud#PRIMITIVES} primitives through
 * {@link Group#intersect}, the framework's closest-hit loop over Surface objects;</li>
 * <li>{@code array}: the same closest-hit loop over the same primitive objects in a plain
 * {@code Surface[]} array; group/array is the price of Group itself (its list, its ray copy);</li>
 * <li>{@code flat}: the same closest-hit search over flat arrays of numbers ({@link FlatSpheres},
 * {@link FlatTriangles}) with the math inlined; group/flat is the price of the object-oriented
 * design as a whole (an object and three or one Vec3 per primitive, a call per test).</li>
 * </ul>
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class IntersectionBench {
    @Param({"sphere", "triangle"})
    public String primitive;

    private Surface[] surfaces;
    private Ray[] rays;
    private Group group;
    private FlatSpheres flatSpheres;
    private FlatTriangles flatTriangles;
    private final double[] t = new double[1];
    private int next;

    @Setup
    public void setUp() {
        PrimitiveCloud cloud = PrimitiveCloud.of(primitive);
        surfaces = cloud.surfaces;
        rays = cloud.rays;
        group = cloud.group();
        if (primitive.equals("sphere")) {
            flatSpheres = new FlatSpheres(surfaces);
        } else {
            flatTriangles = new FlatTriangles(surfaces);
        }
        checkSameHits();
    }

    /** The benchmark compares designs only if both find the same closest hit for every ray. */
    private void checkSameHits() {
        int hits = 0;
        for (Ray ray : rays) {
            IntersectionRecord record = new IntersectionRecord();
            boolean hit = group.intersect(record, ray);
            int k = flatClosest(ray);
            if (hit != (k >= 0) || hit && (record.surface != surfaces[k] || record.t != t[0])) {
                throw new IllegalStateException("flat and group disagree on " + ray);
            }
            hits += hit ? 1 : 0;
        }
        if (hits < rays.length / 10 || hits == rays.length) {
            throw new IllegalStateException("a cloud should stop some rays and miss others; hits: " + hits);
        }
    }

    private int flatClosest(Ray ray) {
        return flatSpheres != null ? flatSpheres.closest(ray, t) : flatTriangles.closest(ray, t);
    }

    private Ray nextRay() {
        return rays[next++ & (PrimitiveCloud.RAYS - 1)];
    }

    @Benchmark
    @OperationsPerInvocation(PrimitiveCloud.PRIMITIVES)
    public int eachTest() {
        IntersectionRecord record = new IntersectionRecord();
        int hits = 0;
        int first = next++;
        for (int k = 0; k < surfaces.length; k++) {
            hits += surfaces[k].intersect(record, rays[(first + k) & (PrimitiveCloud.RAYS - 1)]) ? 1 : 0;
        }
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(PrimitiveCloud.PRIMITIVES)
    public IntersectionRecord group() {
        IntersectionRecord record = new IntersectionRecord();
        group.intersect(record, nextRay());
        return record;
    }

    @Benchmark
    @OperationsPerInvocation(PrimitiveCloud.PRIMITIVES)
    public IntersectionRecord array() {
        IntersectionRecord record = new IntersectionRecord();
        Ray ray = nextRay().copy();
        for (Surface surface : surfaces) {
            if (surface.intersect(record, ray)) {
                ray.end = record.t;
            }
        }
        return record;
    }

    @Benchmark
    @OperationsPerInvocation(PrimitiveCloud.PRIMITIVES)
    public int flat() {
        return flatClosest(nextRay());
    }
}
