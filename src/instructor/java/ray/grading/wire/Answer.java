package ray.grading.wire;

import ray.IntersectionRecord;
import ray.Ray;

/**
 * One answer of an intersect, as data: it returned (hit or not, the record's fields it changed and
 * their new values, the segment ends it changed) or it threw.
 *
 * <p>The rule of a search. A search (a group's loop, a mesh's tree) asks the same surface the same
 * ray with shorter and shorter ends, holding the closest hit so far in the record. For a surface
 * that keeps the contract, one answer tells all the others: a hit at t answers a segment ending
 * after t with the same hit, and one ending at or before t with a miss that leaves the record as it
 * was. {@link #follows} says whether an answer, seen as the base, predicts another this way. The
 * worker checks every prediction against the student's code itself and sends only the answers that
 * differ; the judge applies the rule to the rest. Code that breaks the contract is thereby answered
 * exactly too, just less briefly.
 */
public final class Answer {
    public final int status;
    public final boolean hit;
    /** The record's fields the call changed ({@link Records} bits), their values in {@link #written}. */
    public final int mask;
    public final IntersectionRecord written;
    /** The segment ends the call changed, their values in {@link #start} and {@link #end}. */
    public final int rayMask;
    public final double start;
    public final double end;
    public final ThrownData thrown;

    private Answer(int status, boolean hit, int mask, IntersectionRecord written, int rayMask, double start, double end, ThrownData thrown) {
        this.status = status;
        this.hit = hit;
        this.mask = mask;
        this.written = written;
        this.rayMask = rayMask;
        this.start = start;
        this.end = end;
        this.thrown = thrown;
    }

    /** A returned answer: {@code after} holds the record after the call, {@code before} as it was. */
    public static Answer returned(boolean hit, IntersectionRecord before, IntersectionRecord after, double startBefore, double endBefore,
            Ray rayAfter) {
        IntersectionRecord written = new IntersectionRecord();
        written.set(after);
        return new Answer(Protocol.RETURNED, hit, Records.changes(before, after), written,
                Records.rayChanges(startBefore, endBefore, rayAfter), rayAfter.start, rayAfter.end, null);
    }

    public static Answer threw(ThrownData thrown) {
        return new Answer(Protocol.THREW, false, 0, null, 0, 0, 0, thrown);
    }

    /** A miss that changed nothing: what the rule predicts for a segment that ends too soon. */
    public static final Answer MISS = new Answer(Protocol.RETURNED, false, 0, new IntersectionRecord(), 0, 0, 0, null);

    /** Whether this answer can serve as a base: it returned, left the segment alone, and a hit wrote its t. */
    public boolean isBase() {
        return status == Protocol.RETURNED && rayMask == 0 && (hit ? (mask & Records.T) != 0 : mask == 0);
    }

    /** What this base answer predicts for the same surface and ray (starting at {@code start}) with a segment ending at {@code end}. */
    public Answer predict(double start, double end) {
        return hit && written.t > start && written.t < end ? this : MISS;
    }

    /** Whether {@code other} is exactly the answer {@code predicted}: the same return and the same changes, values by their bits. */
    public static boolean follows(Answer other, Answer predicted) {
        if (other.status != Protocol.RETURNED || other.hit != predicted.hit || other.mask != predicted.mask || other.rayMask != 0) {
            return false;
        }
        IntersectionRecord a = other.written;
        IntersectionRecord b = predicted.written;
        int m = other.mask;
        return ((m & Records.T) == 0 || RecordValues.same(a.t, b.t))
                && ((m & Records.LOCATION) == 0 || RecordValues.same(a.location, b.location))
                && ((m & Records.NORMAL) == 0 || RecordValues.same(a.normal, b.normal))
                && ((m & Records.SURFACE) == 0 || a.surface == b.surface)
                && ((m & Records.BETA) == 0 || RecordValues.same(a.beta, b.beta))
                && ((m & Records.GAMMA) == 0 || RecordValues.same(a.gamma, b.gamma))
                && ((m & Records.TEX_U) == 0 || RecordValues.same(a.texU, b.texU))
                && ((m & Records.TEX_V) == 0 || RecordValues.same(a.texV, b.texV));
    }

    /** Applies this (returned) answer to the caller's record and ray; returns what intersect returned. */
    public boolean applyTo(IntersectionRecord out, Ray ray) {
        Records.apply(mask, written, out);
        if ((rayMask & Records.START) != 0) {
            ray.start = start;
        }
        if ((rayMask & Records.END) != 0) {
            ray.end = end;
        }
        return hit;
    }

    public void write(WireOut out, Refs refs) {
        out.u8(status);
        if (status == Protocol.THREW) {
            thrown.write(out);
            return;
        }
        out.bool(hit);
        Records.writeChanges(out, mask, written, refs);
        out.u8(rayMask);
        if ((rayMask & Records.START) != 0) {
            out.f64(start);
        }
        if ((rayMask & Records.END) != 0) {
            out.f64(end);
        }
    }

    public static Answer read(WireIn in, Refs refs) {
        int status = in.u8();
        if (status == Protocol.THREW) {
            return threw(ThrownData.read(in));
        }
        if (status != Protocol.RETURNED) {
            throw new WireError("an answer of status " + status);
        }
        boolean hit = in.bool();
        IntersectionRecord written = new IntersectionRecord();
        int mask = Records.readChanges(in, written, refs);
        Ray ends = new Ray(null, null, 0, 0);
        int rayMask = Records.readRayChanges(in, ends);
        return new Answer(Protocol.RETURNED, hit, mask, written, rayMask, ends.start, ends.end, null);
    }
}
