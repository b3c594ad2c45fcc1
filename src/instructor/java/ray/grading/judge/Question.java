package ray.grading.judge;

import ray.IntersectionRecord;
import ray.Ray;
import ray.grading.wire.RecordValues;
import ray.math.Vec3;

/**
 * One question a computation asked of the student's code (in the worker), as its log keeps it: what
 * was asked (the target, the ray's origin, direction and segment and the record before; or u and v),
 * and the answer once the worker gave it. A question matches a call that asks exactly the same.
 */
final class Question {
    enum Kind { INTERSECT, ANY_HIT, CAMERA, TEXTURE }

    final Kind kind;
    /** A stand-in, or a set of stand-in triangles searched as a whole. */
    final Object target;
    final Vec3 origin;
    final Vec3 direction;
    final double start;
    final double end;
    /** The record as it was before the call (a copy); null for other kinds. */
    final IntersectionRecord before;
    final double u;
    final double v;
    /** The answer: an Answer (intersect), a Boolean (any hit), a Ray, Vec3 or {@link #NULL} (u, v); or a ThrownData; null while unknown. */
    Object answer;
    /** Sent in a batch whose answer has not come (a question the worker needed more for is sent again). */
    boolean sent;
    /** A hash of what was asked ({@link #intersectHash} and its kin), for finding it in a long log. */
    private final int hash;

    /** What a method of the student's returned when it returned null. */
    static final Object NULL = new Object();

    private Question(Kind kind, Object target, Vec3 origin, Vec3 direction, double start, double end, IntersectionRecord before,
            double u, double v) {
        this.kind = kind;
        this.target = target;
        this.origin = origin;
        this.direction = direction;
        this.start = start;
        this.end = end;
        this.before = before;
        this.u = u;
        this.v = v;
        this.hash = kind == Kind.INTERSECT ? mix(rayHash(target, origin, direction, start, end), RecordValues.hash(before))
                : kind == Kind.ANY_HIT ? rayHash(target, origin, direction, start, end) : uvHash(target, u, v);
    }

    int hash() {
        return hash;
    }

    static int intersectHash(Object target, Ray ray, IntersectionRecord out) {
        return mix(rayHash(target, ray.origin, ray.direction, ray.start, ray.end), RecordValues.hash(out));
    }

    static int anyHitHash(Object target, Ray ray) {
        return rayHash(target, ray.origin, ray.direction, ray.start, ray.end);
    }

    static int uvHash(Object target, double u, double v) {
        return mix(mix(System.identityHashCode(target), Double.hashCode(u)), Double.hashCode(v));
    }

    private static int rayHash(Object target, Vec3 origin, Vec3 direction, double start, double end) {
        int h = System.identityHashCode(target);
        h = mix(h, vecHash(origin));
        h = mix(h, vecHash(direction));
        h = mix(h, Double.hashCode(start));
        return mix(h, Double.hashCode(end));
    }

    private static int vecHash(Vec3 v) {
        return v == null ? 0 : mix(mix(Double.hashCode(v.x), Double.hashCode(v.y)), Double.hashCode(v.z));
    }

    private static int mix(int h, int more) {
        return (h ^ more) * 0x9E3779B1 + (h >>> 16);
    }

    static Question intersect(Object target, Ray ray, IntersectionRecord out) {
        IntersectionRecord before = new IntersectionRecord();
        before.set(out);
        return new Question(Kind.INTERSECT, target, ray.origin, ray.direction, ray.start, ray.end, before, 0, 0);
    }

    /** An intersect question the worker answered unasked (the next end a search will ask), with its answer. */
    static Question answered(Object target, Vec3 origin, Vec3 direction, double start, double end, IntersectionRecord before,
            Object answer) {
        Question q = new Question(Kind.INTERSECT, target, origin, direction, start, end, before, 0, 0);
        q.answer = answer;
        q.sent = true;
        return q;
    }

    static Question anyHit(Object target, Ray ray) {
        return new Question(Kind.ANY_HIT, target, ray.origin, ray.direction, ray.start, ray.end, null, 0, 0);
    }

    static Question uv(Kind kind, Object target, double u, double v) {
        return new Question(kind, target, null, null, 0, 0, null, u, v);
    }

    boolean matchesIntersect(Object target, Ray ray, IntersectionRecord out) {
        return kind == Kind.INTERSECT && this.target == target && sameRay(ray) && RecordValues.same(end, ray.end)
                && RecordValues.equal(before, out);
    }

    boolean matchesAnyHit(Object target, Ray ray) {
        return kind == Kind.ANY_HIT && this.target == target && sameRay(ray) && RecordValues.same(end, ray.end);
    }

    boolean matchesUv(Kind kind, Object target, double u, double v) {
        return this.kind == kind && this.target == target && RecordValues.same(this.u, u) && RecordValues.same(this.v, v);
    }

    /** The same origin, direction and start: vectors by identity first (a search passes on its ray's), else by value. */
    boolean sameRay(Ray ray) {
        return (origin == ray.origin || RecordValues.same(origin, ray.origin))
                && (direction == ray.direction || RecordValues.same(direction, ray.direction)) && RecordValues.same(start, ray.start);
    }

    /** The same origin, direction and start as {@code other}. */
    boolean sameRay(Question other) {
        return (origin == other.origin || RecordValues.same(origin, other.origin))
                && (direction == other.direction || RecordValues.same(direction, other.direction)) && RecordValues.same(start, other.start);
    }

    Ray ray(double segmentEnd) {
        return new Ray(origin, direction, start, segmentEnd);
    }
}
