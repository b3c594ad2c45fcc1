package ray.surface;

import static org.junit.Assert.fail;
import static ray.testing.RandomVectors.randomInBall;
import static ray.testing.RandomVectors.randomUnit;
import static ray.testing.RandomVectors.randomVec;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.Set;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.AnswerRounds;
import ray.scene.ObjReader;
import ray.testing.Hints;
import ray.testing.Points;
import ray.testing.ProjectFolder;
import ray.testing.StudentTaskRule;

/**
 * Bonus (extra credit) tests of Triangle.intersect on the hard numerical cases of docs/numerics.md,
 * where Cramer's rule with the textbook tests can give the wrong answer. Each test is one case, and
 * its failure message names the case, what went wrong and where to read about the fix. A failure
 * costs no regular points.
 *
 * <p>The expected answers are known from how each case is built: rays aimed at points of a closed
 * mesh must hit it; rays aimed well inside a tiny triangle must hit; a triangle without area, and a
 * ray lying exactly in a triangle's plane (integer geometry, so "exactly" holds in double), must
 * miss. Each miss case also checks a control ray that must hit, so that a triangle that never hits
 * fails too. Only Triangle is used (the mesh is looped over here, not put in a Group), and every
 * ray is seeded, so every run sees the same cases.
 */
@Points(value = 1, bonus = true)
public class TriangleHardCasesBonusTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    /**
     * The shipped closed mesh scenes/meshes/icosphere-room.obj (an icosahedron subdivided twice: 320
     * triangles sharing 162 vertices by index, radius 1), moved to a center at distance 1 from the
     * origin, and 5,000 rays from inside it, each aimed exactly at a vertex (one
     * in four) or at a point of an edge, rounded to double. Every ray must hit one of the triangles
     * that meet there at the point it was aimed at (t = 1 within 1e-9): a closed mesh has no cracks. Cramer's rule lets a
     * few percent of such rays through (4.3% over the instructor's sweep of closed meshes); a
     * watertight test, none.
     */
    @Test
    public void closedMeshHasNoCracksAtSharedEdgesAndVertices() {
        Vec3 center = new Vec3(0.6, -0.8, 0);
        IcosphereMesh mesh = new IcosphereMesh(center);
        int rays = 5000;
        // Some 20,000 questions: asked together when grading (AnswerRounds), so the loop only computes.
        Tally tally = AnswerRounds.exactly(() -> {
            Random random = new Random(8_000_001);
            int passedThrough = 0;
            String firstExample = "";
            for (int i = 0; i < rays; i++) {
                Vec3 origin = center.plus(randomInBall(random, 0.5));
                Vec3 target;
                String aim;
                List<Triangle> meeting;
                if (i % 4 == 0) {
                    int k = random.nextInt(mesh.vertices.size());
                    target = mesh.vertices.get(k);
                    aim = "vertex " + k + " " + target;
                    meeting = mesh.meetingAt(k, k);
                } else {
                    int[] edge = mesh.edges.get(random.nextInt(mesh.edges.size()));
                    Vec3 a = mesh.vertices.get(edge[0]);
                    Vec3 b = mesh.vertices.get(edge[1]);
                    target = a.plus(b.minus(a).times(0.05 + 0.9 * random.nextDouble()));
                    aim = "the edge from vertex " + edge[0] + " to vertex " + edge[1] + ", at " + target;
                    meeting = mesh.meetingAt(edge[0], edge[1]);
                }
                Ray ray = new Ray(origin, target.minus(origin));
                boolean hit = false;
                // Only the triangles that meet at the point aimed at can be hit there.
                for (Triangle t : meeting) {
                    IntersectionRecord out = new IntersectionRecord();
                    if (t.intersect(out, ray) && Math.abs(out.t - 1) <= 1e-9) {
                        hit = true;
                        break;
                    }
                }
                if (!hit && passedThrough++ == 0) {
                    firstExample = "the ray from " + origin + " aimed at " + aim;
                }
            }
            return new Tally(passedThrough, firstExample);
        });
        int through = tally.count;
        String example = tally.example;
        if (through == rays) {
            fail("closed mesh: all " + rays + " rays aimed at points of a closed mesh missed every triangle (e.g. " + example
                    + "): this bonus needs ordinary hits to work first");
        }
        if (through > 0) {
            fail("closed mesh: " + through + " of " + rays + " rays aimed exactly at edges and vertices shared by the 320 triangles"
                    + " of a closed mesh (an icosphere, seen from inside) passed between the triangles, hitting none at the point"
                    + " aimed at (e.g. " + example + ")." + Hints.fix(" With Cramer's rule each triangle rounds its own β and γ, so two"
                    + " neighbors can both find a point of their shared edge a hair outside; a watertight test decides a shared"
                    + " edge the same way for both (Woop, Benthin and Wald, \"Watertight Ray/Triangle Intersection\", JCGT 2(1),"
                    + " 2013; docs/numerics.md)"));
        }
    }

    /** How many rays of a case went wrong, and the first of them. */
    private static final class Tally {
        final int count;
        final String example;

        Tally(int count, String example) {
            this.count = count;
            this.example = example;
        }
    }

    /**
     * 3,000 rays at triangles of size 1e-6 to 1e-4 (placed anywhere within 1 of the origin), from
     * 0.5 to 2 sizes away, aimed at a point at least 0.1 inside every edge: each must hit at that
     * point (t, β and γ within 1e-6 relative). Half the rays have a unit direction, half the
     * direction target − origin, of the triangle's size. The determinant of the system scales with
     * the triangle's area times |d|, about 1e-18 here, so a textbook absolute epsilon such as
     * |det| &lt; 1e-8 (or a minimum t) throws hits away: Cramer's rule with that epsilon misses all
     * 3,000 (75 to 100% of such rays in TriangleSweep). With det == 0 as its only parallel test,
     * Cramer's rule hits them all, as does the solution.
     */
    @Test
    public void tinyTriangleSeenFromNearbyIsHit() {
        Random random = new Random(8_000_002);
        int rays = 3000;
        int wrong = 0;
        String example = "";
        for (int i = 0; i < rays; i++) {
            double size = Math.pow(10, -6 + 2 * random.nextDouble());
            Vec3 base = randomVec(random, 1);
            Vec3 v0;
            Vec3 v1;
            Vec3 v2;
            do {
                v0 = base.plus(randomInBall(random, size));
                v1 = base.plus(randomInBall(random, size));
                v2 = base.plus(randomInBall(random, size));
            } while (v1.minus(v0).cross(v2.minus(v0)).length() < 0.2 * size * size);
            Triangle triangle = new Triangle(v0, v1, v2);
            double beta = 0.1 + 0.7 * random.nextDouble();
            double gamma = 0.1 + (0.8 - beta) * random.nextDouble();
            Vec3 target = v0.plus(v1.minus(v0).times(beta)).plus(v2.minus(v0).times(gamma));
            Vec3 normal = triangle.getFaceNormal();
            Vec3 away;
            do {
                away = randomUnit(random);
            } while (Math.abs(away.dot(normal)) < 0.3);
            double distance = size * (0.5 + 1.5 * random.nextDouble());
            Vec3 origin = target.plus(away.times(distance));
            boolean unit = i % 2 == 0;
            Ray ray = new Ray(origin, unit ? away.negate() : target.minus(origin));
            double t = unit ? distance : 1;
            IntersectionRecord out = new IntersectionRecord();
            boolean hit = triangle.intersect(out, ray);
            if (!hit || !(Math.abs(out.t - t) <= 1e-6 * t) || !(Math.abs(out.beta - beta) <= 1e-6)
                    || !(Math.abs(out.gamma - gamma) <= 1e-6)) {
                if (wrong++ == 0) {
                    example = String.format(Locale.ROOT, "%s at a triangle of size %.1g, %s: %s", ray, size, triangle,
                            hit ? "hit at t = " + out.t + ", β = " + out.beta + ", γ = " + out.gamma + " instead of t = " + t
                                    + ", β = " + beta + ", γ = " + gamma
                                    : "missed");
                }
            }
        }
        if (wrong > 0) {
            fail("tiny triangle: " + wrong + " of " + rays + " rays aimed well inside triangles of size 1e-6…1e-4, from 0.5 to 2"
                    + " sizes away, missed or hit the wrong point (e.g. " + example + ")." + Hints.fix(" The determinant scales with the"
                    + " triangle's area times |d| (about 1e-18 here): an absolute epsilon such as |det| < 1e-8, or a minimum t"
                    + " other than ray.start, throws small triangles away; test det == 0 only (docs/numerics.md)"));
        }
    }

    /**
     * 3,000 rays at triangles without area: collinear integer points (a line through an integer
     * point with an integer step, so the triangle is exactly degenerate in double) and triangles with
     * two equal vertices, in every vertex order, each ray aimed at a point of the triangle's segment.
     * Every one must miss and leave the record untouched (no hit, no NaN); each ray must also hit a
     * proper triangle built around the point it aims at (the control). Cramer's rule reports 33 of
     * these 3,000 as hits, with a zero normal (1.3% collinear, 1.1% two vertices equal in
     * TriangleSweep): the rounded determinant of a triangle without area need not be exactly 0.
     */
    @Test
    public void degenerateTrianglesAreMissedCleanly() {
        Random random = new Random(8_000_003);
        int rays = 3000;
        List<String> wrong = new ArrayList<>();
        String controlMissed = null;
        for (int i = 0; i < rays; i++) {
            Vec3 a = integerPoint(random, 100);
            Vec3 b;
            Vec3 c;
            if (i % 2 == 0) {
                Vec3 step;
                do {
                    step = integerPoint(random, 5);
                } while (step.lengthSquared() == 0);
                b = a.plus(step.times(random.nextInt(21) - 10));
                c = a.plus(step.times(random.nextInt(21) - 10));
            } else {
                b = randomVec(random, 100);
                c = a;
            }
            Vec3 target = a.plus(b.minus(a).times(random.nextDouble()));
            Vec3[] v = shuffled(random, a, b, c);
            Triangle degenerate = new Triangle(v[0], v[1], v[2]);
            Vec3 origin = randomVec(random, 200);
            Ray ray = new Ray(origin, target.minus(origin));
            if (controlMissed == null && !hitsControl(random, target, ray)) {
                controlMissed = ray + " aimed at the centroid of a proper triangle around " + target;
            }
            IntersectionRecord out = Records.sentinel(degenerate);
            IntersectionRecord before = Records.copyOf(out);
            boolean hit = degenerate.intersect(out, ray);
            if (hit || !untouched(before, out)) {
                wrong.add(ray + " at " + degenerate + (hit ? ": " + HitMessages.returnedTrue(out, true) + " and the normal " + out.normal
                        : " missed but changed the record"));
            }
        }
        if (controlMissed != null) {
            fail("degenerate triangle: the control ray missed: " + controlMissed + " must hit it at t = 1 (this bonus needs"
                    + " ordinary hits to work first)");
        }
        if (!wrong.isEmpty()) {
            fail("degenerate triangle: " + wrong.size() + " of " + rays + " rays at triangles without area (collinear or repeated"
                    + " vertices) were reported as hits (e.g. " + wrong.get(0) + "). Such a triangle has no inside" + Hints.fix(", but the"
                    + " rounded determinant of its system need not be exactly 0; reject it up front: its edge cross product"
                    + " (v1 − v0) × (v2 − v0) is exactly zero, so getFaceNormal() is the zero vector (docs/numerics.md)") + ".");
        }
    }

    /**
     * 3,000 rays lying exactly in the plane of a triangle with integer vertices up to 2^20 and
     * crossing its interior: the origin is a vertex plus eighths of the edges minus a multiple of the
     * direction, and the direction an integer combination of the edges, all exact in double. A ray
     * in the plane never crosses it: each must miss and leave the record untouched. Each triangle is
     * also hit by a control ray through the same interior point from off the plane. Cramer's rule
     * reports 79 of these 3,000 as hits (2.5% in TriangleSweep): its det is 0 in exact arithmetic
     * but rounds to a small nonzero number.
     */
    @Test
    public void rayInTheTrianglesPlaneMisses() {
        Random random = new Random(8_000_004);
        int rays = 3000;
        List<String> wrong = new ArrayList<>();
        String controlMissed = null;
        for (int i = 0; i < rays; i++) {
            Vec3 v0 = integerPoint(random, 1 << 20);
            Vec3 e1 = integerPoint(random, 1 << 20).minus(v0);
            Vec3 e2 = integerPoint(random, 1 << 20).minus(v0);
            Vec3 along = e1.times(random.nextInt(41) - 20).plus(e2.times(random.nextInt(41) - 20));
            if (e1.cross(e2).lengthSquared() == 0 || along.lengthSquared() == 0) {
                i--;
                continue;
            }
            Triangle triangle = new Triangle(v0, v0.plus(e1), v0.plus(e2));
            int alpha = 1 + random.nextInt(6);
            int beta = 1 + random.nextInt(7 - alpha);
            Vec3 inside = v0.plus(e1.times(alpha / 8.0)).plus(e2.times(beta / 8.0));
            Ray inPlane = new Ray(inside.minus(along.times(7)), along);
            Vec3 lifted = inPlane.origin.plus(triangle.getFaceNormal().times(along.length()));
            Ray control = new Ray(lifted, inside.minus(lifted));
            IntersectionRecord hitRecord = new IntersectionRecord();
            if (controlMissed == null && !(triangle.intersect(hitRecord, control) && Math.abs(hitRecord.t - 1) < 1e-6)) {
                controlMissed = control + " through the interior point " + inside + " of " + triangle;
            }
            IntersectionRecord out = Records.sentinel(triangle);
            IntersectionRecord before = Records.copyOf(out);
            boolean hit = triangle.intersect(out, inPlane);
            if (hit || !untouched(before, out)) {
                wrong.add(inPlane + " in the plane of " + triangle
                        + (hit ? ": " + HitMessages.returnedTrue(out, true) : " missed but changed the record"));
            }
        }
        if (controlMissed != null) {
            fail("ray in the plane: the control ray missed: " + controlMissed + " must hit it at t = 1 (this bonus needs ordinary"
                    + " hits to work first)");
        }
        if (!wrong.isEmpty()) {
            fail("ray in the plane: " + wrong.size() + " of " + rays + " rays lying exactly in a triangle's plane (integer geometry)"
                    + " and crossing its interior were reported as hits (e.g. " + wrong.get(0) + ")." + Hints.fix(" The system's determinant"
                    + " is 0 in exact arithmetic, but with coordinates up to 2^20 it rounds to a small nonzero number, and the"
                    + " rounded β and γ can land inside; a robust test decides whether d is parallel to the plane without that"
                    + " rounding (docs/numerics.md, \"Rays parallel to the plane\")"));
        }
    }

    /** Whether the ray (aimed at target) hits a proper triangle whose centroid is target, at t ≈ 1. */
    private static boolean hitsControl(Random random, Vec3 target, Ray ray) {
        Vec3 u = randomVec(random, 10);
        Vec3 w = randomVec(random, 10);
        Vec3 normal = u.cross(w);
        if (Math.abs(normal.normalized().dot(ray.direction.normalized())) < 0.2) {
            // Nearly edge-on to the ray: pick the triangle facing it instead.
            Vec3 d = ray.direction.normalized();
            u = d.cross(new Vec3(0.6, 0.8, 0)).times(10);
            if (u.lengthSquared() < 1) {
                u = d.cross(new Vec3(0, 0, 1)).times(10);
            }
            w = d.cross(u);
        }
        Triangle control = new Triangle(target.plus(u), target.plus(w), target.minus(u).minus(w));
        IntersectionRecord out = new IntersectionRecord();
        return control.intersect(out, ray) && Math.abs(out.t - 1) < 1e-6;
    }

    private static boolean untouched(IntersectionRecord before, IntersectionRecord after) {
        return Double.compare(before.t, after.t) == 0 && before.location == after.location && before.normal == after.normal
                && before.surface == after.surface && Double.compare(before.beta, after.beta) == 0
                && Double.compare(before.gamma, after.gamma) == 0;
    }

    /**
     * The shipped icosphere mesh moved to {@code center}, as the vertices, triangles and edges the
     * test walks. Neighboring triangles share vertices by index (the very same Vec3), as a mesh does.
     */
    private static final class IcosphereMesh {
        final List<Vec3> vertices = new ArrayList<>();
        final List<Triangle> triangles = new ArrayList<>();
        final List<int[]> edges = new ArrayList<>();
        /** Each triangle's three vertex indices. */
        final List<int[]> corners = new ArrayList<>();

        IcosphereMesh(Vec3 center) {
            MeshData data = ObjReader.read(ProjectFolder.resolve("scenes", "meshes", "icosphere-room.obj"));
            double[] p = data.positions;
            for (int i = 0; i < p.length; i += 3) {
                vertices.add(new Vec3(p[i], p[i + 1], p[i + 2]).plus(center));
            }
            int[] tri = data.triangles;
            Set<Long> seen = new HashSet<>();
            for (int k = 0; k < tri.length; k += 3) {
                triangles.add(new Triangle(vertices.get(tri[k]), vertices.get(tri[k + 1]), vertices.get(tri[k + 2])));
                corners.add(new int[] {tri[k], tri[k + 1], tri[k + 2]});
                for (int e = 0; e < 3; e++) {
                    int i = Math.min(tri[k + e], tri[k + (e + 1) % 3]);
                    int j = Math.max(tri[k + e], tri[k + (e + 1) % 3]);
                    if (seen.add((long) i << 32 | j)) {
                        edges.add(new int[] {i, j});
                    }
                }
            }
            if (triangles.size() != 320 || vertices.size() != 162 || edges.size() != 480) {
                throw new IllegalStateException("the test's icosphere is broken: " + triangles.size() + " triangles");
            }
        }

        /** The triangles that have both vertex {@code i} and vertex {@code j} (i = j: those that meet at vertex i). */
        List<Triangle> meetingAt(int i, int j) {
            List<Triangle> meeting = new ArrayList<>();
            for (int k = 0; k < triangles.size(); k++) {
                int[] c = corners.get(k);
                boolean hasI = c[0] == i || c[1] == i || c[2] == i;
                boolean hasJ = c[0] == j || c[1] == j || c[2] == j;
                if (hasI && hasJ) {
                    meeting.add(triangles.get(k));
                }
            }
            return meeting;
        }
    }

    private static Vec3[] shuffled(Random random, Vec3 a, Vec3 b, Vec3 c) {
        Vec3[] v = {a, b, c};
        for (int i = 2; i > 0; i--) {
            int j = random.nextInt(i + 1);
            Vec3 swap = v[i];
            v[i] = v[j];
            v[j] = swap;
        }
        return v;
    }

    private static Vec3 integerPoint(Random random, int extent) {
        return new Vec3(random.nextInt(2 * extent + 1) - extent, random.nextInt(2 * extent + 1) - extent,
                random.nextInt(2 * extent + 1) - extent);
    }
}
