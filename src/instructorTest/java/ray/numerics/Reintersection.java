package ray.numerics;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.render.RayOffsets;
import ray.render.SecondaryRays;
import ray.surface.Group;
import ray.surface.HitGeometry;
import ray.surface.Mesh;
import ray.surface.MeshData;
import ray.surface.Placement;
import ray.surface.Placements;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Transformed;
import ray.surface.Triangle;

/**
 * The re-intersection ("shadow acne") catalogue shared by {@link ReintersectionTest} and
 * {@link ReintersectionSweep}: hit points on random convex surfaces, and new rays from them that
 * cannot meet the same surface again, so that any hit the surface reports for them is a
 * self-intersection.
 *
 * <p>Surfaces have sizes and positions (distance from the origin) 10^U(−4, 6), drawn independently
 * as in pbrt-v4's {@code Triangle.Reintersect} and {@code FullSphere.Reintersect} tests, and each
 * is hit by a camera-like ray from 10^U(−2, 3) sizes away ({@link Kind} lists the variations).
 * From each hit:
 * <ul>
 * <li>leaving rays: directions into the open half-space in front of the hit's tangent plane (or the
 *     triangle's plane, on the side the camera ray came from), half uniform, half grazing (normal
 *     component 10^U(−8, −1)). A convex surface lies behind that plane, so such a ray cannot meet it;</li>
 * <li>shadow rays: toward a light in that half-space 10^U(−2, 3) sizes away, at least {@link #margin}
 *     above the plane; and on a closed surface hit from inside, toward a light inside at least
 *     {@link #margin} from every wall (a segment from a boundary point of a convex body to an
 *     interior point meets the boundary only at its start).</li>
 * </ul>
 */
final class Reintersection {
    /** How new rays leave a hit: the renderer's way or another, for comparison. */
    interface Spawner {
        Ray leaving(IntersectionRecord hit, HitGeometry g, Vec3 direction);

        Ray toLight(IntersectionRecord hit, HitGeometry g, Vec3 lightPosition);
    }

    /** The renderer's rays ({@link SecondaryRays}). */
    static final Spawner FRAMEWORK = new Spawner() {
        @Override
        public Ray leaving(IntersectionRecord hit, HitGeometry g, Vec3 direction) {
            return SecondaryRays.reflectionRay(g, direction);
        }

        @Override
        public Ray toLight(IntersectionRecord hit, HitGeometry g, Vec3 lightPosition) {
            return SecondaryRays.shadowRay(g, lightPosition);
        }

        @Override
        public String toString() {
            return "framework (" + (int) SecondaryRays.OFFSET_ULPS + " eps scale)";
        }
    };

    /** pbrt-v4's rule: off the re-projected hit by its own error bound ({@link RayOffsets#ERROR_BOUND}). */
    static final Spawner ERROR_BOUND = new Spawner() {
        @Override
        public Ray leaving(IntersectionRecord hit, HitGeometry g, Vec3 direction) {
            return RayOffsets.ERROR_BOUND.reflectionRay(g, direction);
        }

        @Override
        public Ray toLight(IntersectionRecord hit, HitGeometry g, Vec3 lightPosition) {
            return RayOffsets.ERROR_BOUND.shadowRay(g, lightPosition);
        }

        @Override
        public String toString() {
            return "error bound";
        }
    };

    /** The error-bound rule with the offset {@code multiple} times the bound. */
    static Spawner errorBound(double multiple) {
        return new Spawner() {
            @Override
            public Ray leaving(IntersectionRecord hit, HitGeometry g, Vec3 direction) {
                return new Ray(SecondaryRays.errorBoundOrigin(g, direction, multiple), direction);
            }

            @Override
            public Ray toLight(IntersectionRecord hit, HitGeometry g, Vec3 lightPosition) {
                Vec3 origin = SecondaryRays.errorBoundOrigin(g, lightPosition.minus(g.point), multiple);
                return new Ray(origin, lightPosition.minus(origin), 0, SecondaryRays.SHADOW_END);
            }

            @Override
            public String toString() {
                return (long) multiple + " x error bound";
            }
        };
    }

    /** From the hit point itself with t_min = 0: the textbook's first attempt. */
    static final Spawner NO_OFFSET = fixedStart(0);

    /** From the hit point with a unit direction and a fixed t_min = {@code epsilon}. */
    static Spawner fixedStart(double epsilon) {
        return new Spawner() {
            @Override
            public Ray leaving(IntersectionRecord hit, HitGeometry g, Vec3 direction) {
                return new Ray(hit.location, direction.normalized(), epsilon, Double.POSITIVE_INFINITY);
            }

            @Override
            public Ray toLight(IntersectionRecord hit, HitGeometry g, Vec3 lightPosition) {
                Vec3 toLight = lightPosition.minus(hit.location);
                double distance = toLight.length();
                return new Ray(hit.location, toLight.times(1 / distance), epsilon, distance - epsilon);
            }

            @Override
            public String toString() {
                return epsilon == 0 ? "no offset (t_min 0)" : "fixed t_min " + epsilon;
            }
        };
    }

    /**
     * The renderer's rule before issue 4: 1e-9·(1 + max|p_i|) from the reported hit point along the
     * reported (shading) normal, on the side the new ray leaves to (Mitsuba's form of the offset).
     */
    static final Spawner RELATIVE_1E9 = new Spawner() {
        private Vec3 origin(IntersectionRecord hit, Vec3 direction) {
            double offset = 1e-9 * (1 + hit.location.maxAbs());
            return hit.location.plusScaled(hit.normal.dot(direction) >= 0 ? offset : -offset, hit.normal);
        }

        @Override
        public Ray leaving(IntersectionRecord hit, HitGeometry g, Vec3 direction) {
            return new Ray(origin(hit, direction), direction);
        }

        @Override
        public Ray toLight(IntersectionRecord hit, HitGeometry g, Vec3 lightPosition) {
            Vec3 origin = origin(hit, lightPosition.minus(hit.location));
            return new Ray(origin, lightPosition.minus(origin), 0, SecondaryRays.SHADOW_END);
        }

        @Override
        public String toString() {
            return "1e-9(1+max|p|) shading n";
        }
    };

    /** The renderer's rule with {@code ulps} in place of {@link SecondaryRays#OFFSET_ULPS}. */
    static Spawner geometryOffset(double ulps) {
        return new Spawner() {
            private Vec3 origin(HitGeometry g, Vec3 direction) {
                double offset = ulps * 0x1p-53 * g.scale;
                return g.point.plusScaled(g.normal.dot(direction) >= 0 ? offset : -offset, g.normal);
            }

            @Override
            public Ray leaving(IntersectionRecord hit, HitGeometry g, Vec3 direction) {
                return new Ray(origin(g, direction), direction);
            }

            @Override
            public Ray toLight(IntersectionRecord hit, HitGeometry g, Vec3 lightPosition) {
                Vec3 origin = origin(g, lightPosition.minus(g.point));
                return new Ray(origin, lightPosition.minus(origin), 0, SecondaryRays.SHADOW_END);
            }

            @Override
            public String toString() {
                return (long) ulps + " eps scale";
            }
        };
    }

    /** The kinds of surface hit. */
    enum Kind {
        /** A sphere, hit from outside. */
        SPHERE,
        /** A sphere hit from inside (the camera in the sphere); shadow rays go to lights inside. */
        SPHERE_INSIDE,
        /** A sphere of radius 1 in a group scaled non-uniformly (an ellipsoid), rotated and translated: a Transformed. */
        TRANSFORMED_SPHERE,
        /** A huge sphere (radius 10^U(3, 7)) whose top touches the origin, hit within 10^U(−3, 2) of it: a ground. */
        GROUND_SPHERE,
        /** A triangle, hit on either side. */
        TRIANGLE,
        /** A thin triangle: its third vertex 10^U(−6, −1) of the first edge's length off that edge's line. */
        SLIVER_TRIANGLE,
        /** A triangle seen from 10^U(3, 7) sizes away (a far camera), so that the hit's t·d is long. */
        TRIANGLE_FROM_AFAR,
        /** A triangle with vertex normals up to 60° from its face normal; rays leave on the geometric side. */
        SMOOTH_TRIANGLE,
        /** A triangle in a rotated, non-uniformly scaled, translated group. */
        TRANSFORMED_TRIANGLE,
        /** A closed convex mesh (an icosphere of 80 faces, shared vertices) hit near its edges and vertices, from outside. */
        CLOSED_MESH,
        /** The same mesh hit from inside; shadow rays go to lights inside, across the neighbours' edges. */
        CLOSED_MESH_INSIDE,
    }

    /** Counts of one run. */
    static final class Tally {
        long leaving;
        long leavingRehits;
        long shadow;
        long shadowRehits;
        /** Camera rays that missed the surface they were aimed at (the case is skipped; should be rare). */
        long primaryMisses;
        /** One example of a re-hit, for failure messages. */
        String example;

        long rays() {
            return leaving + shadow;
        }

        long rehits() {
            return leavingRehits + shadowRehits;
        }

        double rate() {
            return rehits() / (double) Math.max(1, rays());
        }

        @Override
        public String toString() {
            return String.format("%d of %d leaving rays and %d of %d shadow rays re-hit (%.4f%%)%s",
                    leavingRehits, leaving, shadowRehits, shadow, 100 * rate(),
                    example == null ? "" : "; e.g. " + example);
        }
    }

    private final Random rng;
    private final Spawner spawner;
    private final boolean textbook;
    private final Tally tally = new Tally();
    private final Map<Surface, Placements> placements = new IdentityHashMap<>();
    /**
     * How far lights stay from the surface: 1e-6 of its size plus 1e-12 of its distance from the
     * origin (about 10^4 ulps there). A light closer than that is on the surface as far as its
     * rounded coordinates can tell, and whether it is shadowed is not a question of offsets.
     */
    private double margin;

    /** Sizes are 10^U(sizeExponents[0], sizeExponents[1]), distances from the origin 10^U(positionExponents[0], [1]). */
    private final double[] sizeExponents;
    private final double[] positionExponents;

    private Reintersection(long seed, Spawner spawner, boolean textbook, double[] sizeExponents, double[] positionExponents) {
        this.rng = new Random(seed);
        this.spawner = spawner;
        this.textbook = textbook;
        this.sizeExponents = sizeExponents;
        this.positionExponents = positionExponents;
    }

    /**
     * Runs {@code surfaces} random surfaces of {@code kind}, one hit on each, with {@code raysPerHit}
     * leaving and as many shadow rays from it. With {@code textbook}, spheres and triangles
     * intersect as a student's first solution might ({@link QuadraticSphere}, {@link CramerTriangle})
     * instead of the solution's robust code: the renderer's offsets must hold for both.
     */
    static Tally run(Kind kind, Spawner spawner, boolean textbook, long seed, int surfaces, int raysPerHit) {
        return run(kind, spawner, textbook, seed, surfaces, raysPerHit, new double[] {-4, 6}, new double[] {-4, 6});
    }

    /** The same with sizes 10^U(sizeExponents) and distances from the origin 10^U(positionExponents). */
    static Tally run(Kind kind, Spawner spawner, boolean textbook, long seed, int surfaces, int raysPerHit,
            double[] sizeExponents, double[] positionExponents) {
        Reintersection r = new Reintersection(seed, spawner, textbook, sizeExponents, positionExponents);
        for (int i = 0; i < surfaces; i++) {
            r.one(kind, raysPerHit);
        }
        return r.tally;
    }

    /** 10^U(lo, hi). */
    private double exp10(double lo, double hi) {
        return Math.pow(10, lo + (hi - lo) * rng.nextDouble());
    }

    private Vec3 unit() {
        return new Vec3(rng.nextGaussian(), rng.nextGaussian(), rng.nextGaussian()).normalized();
    }

    /** A unit direction with positive component along unit {@code n}: uniform half the time, else grazing. */
    private Vec3 into(Vec3 n) {
        Vec3 w = unit();
        if (rng.nextBoolean()) {
            return w.dot(n) < 0 ? w.minus(n.times(2 * w.dot(n))) : w;
        }
        Vec3 tangent = w.minus(n.times(w.dot(n))).normalized();
        return tangent.plus(n.times(exp10(-8, -1))).normalized();
    }

    private Sphere sphere(Vec3 center, double radius) {
        Sphere s = textbook ? new QuadraticSphere() : new Sphere();
        s.setCenter(center);
        s.setRadius(radius);
        s.complete();
        return s;
    }

    private Triangle triangle(Vec3 a, Vec3 b, Vec3 c, Vec3... normals) {
        if (normals.length == 3) {
            return textbook ? new CramerTriangle(a, b, c, normals[0], normals[1], normals[2])
                    : new Triangle(a, b, c, normals[0], normals[1], normals[2]);
        }
        return textbook ? new CramerTriangle(a, b, c) : new Triangle(a, b, c);
    }

    /** A group holding {@code surface}, scaled non-uniformly by 1…3 times {@code size}, rotated at random and moved to {@code position}. */
    private Transformed placed(Surface surface, double size, Vec3 position) {
        Group group = new Group();
        group.addSurface(surface);
        Vec3 scale = new Vec3(size * (1 + 2 * rng.nextDouble()), size * (1 + 2 * rng.nextDouble()), size * (1 + 2 * rng.nextDouble()));
        Vec3 rotate = new Vec3(360 * rng.nextDouble(), 360 * rng.nextDouble(), 360 * rng.nextDouble());
        return (Transformed) Placement.of(position, rotate, scale).place(group);
    }

    private void one(Kind kind, int raysPerHit) {
        double size = exp10(sizeExponents[0], sizeExponents[1]);
        Vec3 position = unit().times(exp10(positionExponents[0], positionExponents[1]));
        margin = 1e-6 * size + 1e-12 * position.length();
        switch (kind) {
            case SPHERE:
            case SPHERE_INSIDE: {
                Sphere sphere = sphere(position, size);
                boolean inside = kind == Kind.SPHERE_INSIDE;
                Vec3 origin = inside
                        ? position.plus(unit().times(size * 0.9 * rng.nextDouble()))
                        : position.plus(unit().times(size * (1 + exp10(-2, 3))));
                Vec3 target = position.plus(unit().times(size * 0.99 * rng.nextDouble()));
                IntersectionRecord hit = primary(sphere, origin, target.minus(origin));
                if (hit == null) {
                    return;
                }
                if (inside) {
                    Vec3 outward = hit.normal.normalized();
                    insideRays(sphere, hit, outward.negate(), w -> 2 * size * -outward.dot(w),
                            x -> size - x.minus(position).length(), raysPerHit);
                } else {
                    outsideRays(sphere, hit, hit.normal, size, raysPerHit);
                }
                return;
            }
            case TRANSFORMED_SPHERE: {
                Transformed ellipsoid = placed(sphere(unit().times(rng.nextDouble()), 1), size, position);
                // The ellipsoid lies within 6 sizes of position; aim at its middle from outside.
                Vec3 origin = position.plus(unit().times(size * (8 + exp10(-1, 3))));
                Vec3 target = position.plus(unit().times(size * 0.5 * rng.nextDouble()));
                IntersectionRecord hit = primary(ellipsoid, origin, target.minus(origin));
                if (hit == null) {
                    return;
                }
                outsideRays(ellipsoid, hit, hit.normal, size, raysPerHit);
                return;
            }
            case GROUND_SPHERE: {
                double radius = exp10(3, 7);
                Sphere ground = sphere(new Vec3(0, -radius, 0), radius);
                double reach = exp10(-3, 2);
                margin = 1e-6 * reach + 1e-12 * radius;
                Vec3 target = new Vec3(reach * rng.nextGaussian(), 0, reach * rng.nextGaussian());
                Vec3 origin = target.plus(new Vec3(rng.nextGaussian(), Math.abs(rng.nextGaussian()) + 0.05, rng.nextGaussian())
                        .times(reach * exp10(-1, 1)));
                IntersectionRecord hit = primary(ground, origin, target.minus(origin));
                if (hit == null) {
                    return;
                }
                outsideRays(ground, hit, hit.normal, reach, raysPerHit);
                return;
            }
            case TRIANGLE:
            case SLIVER_TRIANGLE:
            case TRIANGLE_FROM_AFAR:
            case SMOOTH_TRIANGLE:
            case TRANSFORMED_TRIANGLE: {
                boolean transformed = kind == Kind.TRANSFORMED_TRIANGLE;
                // A transformed triangle has unit size around its group's origin; the group places it.
                Vec3 center = transformed ? Vec3.ZERO : position;
                double s = transformed ? 1 : size;
                Vec3 a = center.plus(unit().times(s));
                Vec3 b = center.plus(unit().times(s));
                Vec3 c = center.plus(unit().times(s));
                if (kind == Kind.SLIVER_TRIANGLE) {
                    Vec3 edge = b.minus(a);
                    Vec3 across = unit().cross(edge).normalized();
                    c = a.plus(edge.times(-0.5 + 2 * rng.nextDouble())).plus(across.times(edge.length() * exp10(-6, -1)));
                }
                Vec3 faceNormal = b.minus(a).cross(c.minus(a)).normalized();
                Triangle triangle = kind == Kind.SMOOTH_TRIANGLE
                        ? triangle(a, b, c, tilted(faceNormal), tilted(faceNormal), tilted(faceNormal))
                        : triangle(a, b, c);
                Surface surface = transformed ? placed(triangle, size, position) : triangle;
                // A point of the triangle, a third of the time within 10^U(−9, −1) of its edge v0v2.
                double u = rng.nextInt(3) == 0 ? exp10(-9, -1) : rng.nextDouble();
                double v = rng.nextDouble() * (1 - u);
                Vec3 local = a.plus(b.minus(a).times(u)).plus(c.minus(a).times(v));
                Vec3 target = transformed ? ((Transformed) surface).toWorld().applyToPoint(local) : local;
                double distance = size * (kind == Kind.TRIANGLE_FROM_AFAR ? exp10(3, 7) : exp10(-2, 3));
                Vec3 origin = target.plus(unit().times(distance));
                IntersectionRecord hit = primary(surface, origin, target.minus(origin));
                if (hit == null) {
                    return;
                }
                // The side the camera ray came from, by the world-space face normal.
                Vec3 worldFace = transformed
                        ? ((Transformed) surface).toWorld().inverse().applyTransposeToVector(faceNormal).normalized()
                        : faceNormal;
                Vec3 side = worldFace.dot(origin.minus(hit.location)) > 0 ? worldFace : worldFace.negate();
                outsideRays(surface, hit, side, size, raysPerHit);
                return;
            }
            case CLOSED_MESH:
            case CLOSED_MESH_INSIDE: {
                ConvexMesh mesh = new ConvexMesh(position, size);
                boolean inside = kind == Kind.CLOSED_MESH_INSIDE;
                // Aim at a face point near its edges or corners, where neighbours meet.
                int face = rng.nextInt(mesh.faceCount());
                double u = rng.nextBoolean() ? exp10(-12, -2) : rng.nextDouble();
                double v = rng.nextBoolean() ? exp10(-12, -2) : rng.nextDouble() * (1 - u);
                Vec3 target = mesh.pointOn(face, u, v);
                Vec3 origin = inside
                        ? position.plus(unit().times(size * 0.7 * rng.nextDouble()))
                        : target.plus(mesh.faceNormal(face).plus(unit()).normalized().times(size * exp10(-2, 3)));
                IntersectionRecord hit = primary(mesh.surface, origin, target.minus(origin));
                if (hit == null) {
                    return;
                }
                if (inside) {
                    insideRays(mesh.surface, hit, hit.normal.normalized().negate(), w -> mesh.exitDistance(hit.location, w), mesh::depth, raysPerHit);
                } else {
                    outsideRays(mesh.surface, hit, hit.normal, size, raysPerHit);
                }
                return;
            }
            default:
                throw new AssertionError(kind);
        }
    }

    /** A unit vector up to 60° from unit {@code n}. */
    private Vec3 tilted(Vec3 n) {
        Vec3 w = unit();
        Vec3 tangent = w.minus(n.times(w.dot(n))).normalized();
        double angle = Math.toRadians(60) * rng.nextDouble();
        return n.times(Math.cos(angle)).plus(tangent.times(Math.sin(angle)));
    }

    /** The renderer's geometry of a hit that {@code surface} reported, as a scene of that surface measures it. */
    private HitGeometry geometry(Surface surface, IntersectionRecord hit) {
        return placements.computeIfAbsent(surface, Placements::of).geometryOf(hit);
    }

    private IntersectionRecord primary(Surface surface, Vec3 origin, Vec3 direction) {
        IntersectionRecord hit = new IntersectionRecord();
        if (!surface.intersect(hit, new Ray(origin, direction))) {
            tally.primaryMisses++;
            return null;
        }
        return hit;
    }

    /** Leaving and shadow rays into the open half-space that {@code outward} points to, where the surface is not. */
    private void outsideRays(Surface surface, IntersectionRecord hit, Vec3 outward, double size, int raysPerHit) {
        // A textbook sphere's normal (p − c)/r is not unit when its hit point p is off the sphere.
        Vec3 side = outward.normalized();
        HitGeometry g = geometry(surface, hit);
        IntersectionRecord scratch = new IntersectionRecord();
        for (int k = 0; k < raysPerHit; k++) {
            tally.leaving++;
            Ray leaving = spawner.leaving(hit, g, into(side));
            if (surface.intersect(scratch, leaving)) {
                tally.leavingRehits++;
                note(hit, leaving, scratch);
            }
            Vec3 light = lightAbove(hit.location, side, size);
            if (light == null) {
                continue;
            }
            tally.shadow++;
            Ray shadow = spawner.toLight(hit, g, light);
            if (surface.intersect(scratch, shadow)) {
                tally.shadowRehits++;
                note(hit, shadow, scratch);
            }
        }
    }

    /** A light 10^U(−2, 3) sizes from {@code p} in the half-space of {@code side}, at least {@link #margin} above its plane. */
    private Vec3 lightAbove(Vec3 p, Vec3 side, double size) {
        for (int tries = 0; tries < 1000; tries++) {
            Vec3 w = into(side);
            double distance = size * exp10(-2, 3);
            if (distance * w.dot(side) >= margin) {
                return p.plus(w.times(distance));
            }
        }
        return null;
    }

    /** How far a ray from a boundary point goes along an inward unit direction before it leaves the body. */
    interface Chord {
        double along(Vec3 w);
    }

    /** How deep a point is inside a closed convex body (negative outside). */
    interface Depth {
        double of(Vec3 point);
    }

    /** Shadow rays from a hit on the inside of a closed convex surface to lights inside it, at least {@link #margin} from every wall. */
    private void insideRays(Surface surface, IntersectionRecord hit, Vec3 inward, Chord chord, Depth depth, int raysPerHit) {
        HitGeometry g = geometry(surface, hit);
        IntersectionRecord scratch = new IntersectionRecord();
        for (int k = 0; k < raysPerHit; k++) {
            Vec3 light = null;
            for (int tries = 0; tries < 1000 && light == null; tries++) {
                Vec3 w = into(inward);
                Vec3 candidate = hit.location.plus(w.times(chord.along(w) * rng.nextDouble()));
                if (depth.of(candidate) >= margin) {
                    light = candidate;
                }
            }
            if (light == null) {
                continue;
            }
            tally.shadow++;
            Ray shadow = spawner.toLight(hit, g, light);
            if (surface.intersect(scratch, shadow)) {
                tally.shadowRehits++;
                note(hit, shadow, scratch);
            }
        }
    }

    private void note(IntersectionRecord hit, Ray ray, IntersectionRecord again) {
        if (tally.example == null) {
            tally.example = "from " + hit + " the " + ray + " hit " + again.surface + " again at t = " + again.t + ", " + again.location;
        }
    }

    /**
     * An icosahedron subdivided once (80 faces, 42 shared vertices) on a sphere: a closed convex mesh,
     * a {@link Mesh} of the solution's triangles or a group of {@link CramerTriangle}s sharing vertices.
     */
    final class ConvexMesh {
        final Surface surface;
        private final Vec3[] vertices;
        private final int[] faces;

        ConvexMesh(Vec3 center, double radius) {
            double g = (1 + Math.sqrt(5)) / 2;
            List<Vec3> unit = new ArrayList<>();
            double[][] corners = {
                {-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1},
            };
            for (double[] c : corners) {
                unit.add(new Vec3(c[0], c[1], c[2]).normalized());
            }
            // Counter-clockwise seen from outside, so (v1 − v0) × (v2 − v0) points outward.
            int[] ico = {
                0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
                3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1,
            };
            faces = new int[4 * ico.length];
            Map<Long, Integer> midpoints = new HashMap<>();
            int k = 0;
            for (int f = 0; f < ico.length; f += 3) {
                int a = ico[f], b = ico[f + 1], c = ico[f + 2];
                int ab = midpoint(unit, midpoints, a, b);
                int bc = midpoint(unit, midpoints, b, c);
                int ca = midpoint(unit, midpoints, c, a);
                for (int corner : new int[] {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca}) {
                    faces[k++] = corner;
                }
            }
            vertices = new Vec3[unit.size()];
            double[] positions = new double[3 * vertices.length];
            for (int i = 0; i < vertices.length; i++) {
                vertices[i] = center.plus(unit.get(i).times(radius));
                positions[3 * i] = vertices[i].x;
                positions[3 * i + 1] = vertices[i].y;
                positions[3 * i + 2] = vertices[i].z;
            }
            if (textbook) {
                Group group = new Group();
                for (int f = 0; f < faceCount(); f++) {
                    group.addSurface(triangle(vertex(f, 0), vertex(f, 1), vertex(f, 2)));
                }
                surface = group.complete();
            } else {
                Mesh mesh = new Mesh();
                mesh.setData(new MeshData(positions, null, faces, null));
                surface = mesh.complete();
            }
        }

        private int midpoint(List<Vec3> unit, Map<Long, Integer> cache, int a, int b) {
            long key = Math.min(a, b) * 1_000_000L + Math.max(a, b);
            return cache.computeIfAbsent(key, ignored -> {
                unit.add(unit.get(a).plus(unit.get(b)).normalized());
                return unit.size() - 1;
            });
        }

        int faceCount() {
            return faces.length / 3;
        }

        Vec3 vertex(int face, int corner) {
            return vertices[faces[3 * face + corner]];
        }

        Vec3 faceNormal(int face) {
            Vec3 a = vertex(face, 0);
            return vertex(face, 1).minus(a).cross(vertex(face, 2).minus(a)).normalized();
        }

        /** The point a + u(b − a) + v(c − a) of a face. */
        Vec3 pointOn(int face, double u, double v) {
            Vec3 a = vertex(face, 0);
            return a.plus(vertex(face, 1).minus(a).times(u)).plus(vertex(face, 2).minus(a).times(v));
        }

        /** The distance from {@code x} to the nearest face plane, positive inside. */
        double depth(Vec3 x) {
            double least = Double.POSITIVE_INFINITY;
            for (int f = 0; f < faceCount(); f++) {
                least = Math.min(least, faceNormal(f).dot(vertex(f, 0).minus(x)));
            }
            return least;
        }

        /** How far a ray from {@code p} (on or in the mesh) goes along unit {@code w} to the nearest face plane ahead. */
        double exitDistance(Vec3 p, Vec3 w) {
            double best = Double.POSITIVE_INFINITY;
            for (int f = 0; f < faceCount(); f++) {
                Vec3 n = faceNormal(f);
                double toward = n.dot(w);
                if (toward > 0) {
                    double distance = n.dot(vertex(f, 0).minus(p)) / toward;
                    if (distance > 0) {
                        best = Math.min(best, distance);
                    }
                }
            }
            return best;
        }
    }

    /**
     * A sphere as a student's first Task 2 solution might intersect it: the textbook discriminant
     * b² − 4ac, roots (−b ± √Δ)/2a, the hit at ray.pointAt(t) with no re-projection. Never ships.
     */
    static final class QuadraticSphere extends Sphere {
        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            Vec3 d = ray.direction;
            Vec3 f = ray.origin.minus(getCenter());
            double a = d.dot(d);
            double b = 2 * d.dot(f);
            double c = f.dot(f) - getRadius() * getRadius();
            double discriminant = b * b - 4 * a * c;
            if (!(discriminant >= 0)) {
                return false;
            }
            double root = Math.sqrt(discriminant);
            double t = (-b - root) / (2 * a);
            if (!(t > ray.start && t < ray.end)) {
                t = (-b + root) / (2 * a);
                if (!(t > ray.start && t < ray.end)) {
                    return false;
                }
            }
            out.t = t;
            out.location = ray.pointAt(t);
            out.normal = out.location.minus(getCenter()).times(1 / getRadius());
            out.surface = this;
            return true;
        }
    }

    /**
     * A triangle as a student's Task 3 solution intersects it: the system
     * β(v0 − v1) + γ(v0 − v2) + t·d = v0 − p solved by Cramer's rule (Shirley and Marschner §4.4.2),
     * the hit at ray.pointAt(t). Never ships.
     */
    static final class CramerTriangle extends Triangle {
        CramerTriangle(Vec3 v0, Vec3 v1, Vec3 v2) {
            super(v0, v1, v2);
        }

        CramerTriangle(Vec3 v0, Vec3 v1, Vec3 v2, Vec3 n0, Vec3 n1, Vec3 n2) {
            super(v0, v1, v2, n0, n1, n2);
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            Vec3 a = getV0().minus(getV1());
            Vec3 b = getV0().minus(getV2());
            Vec3 d = ray.direction;
            Vec3 r = getV0().minus(ray.origin);
            // det[a b d] = a·(b × d); each unknown replaces its column by r.
            double det = a.dot(b.cross(d));
            if (det == 0) {
                return false;
            }
            double beta = r.dot(b.cross(d)) / det;
            double gamma = a.dot(r.cross(d)) / det;
            double t = a.dot(b.cross(r)) / det;
            if (!(beta >= 0 && gamma >= 0 && beta + gamma <= 1 && t > ray.start && t < ray.end)) {
                return false;
            }
            out.t = t;
            out.location = ray.pointAt(t);
            out.normal = normalAt(beta, gamma);
            out.surface = this;
            out.beta = beta;
            out.gamma = gamma;
            return true;
        }
    }
}
