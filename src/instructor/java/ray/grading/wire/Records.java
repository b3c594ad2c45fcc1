package ray.grading.wire;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Rays and intersection records on the wire. A call's answer carries only what the student's code
 * changed, field by field: a field it left alone stays the very object it was on the judge's side,
 * which is what a test of "a miss leaves the record untouched" compares.
 */
public final class Records {
    /** The bits of a changed-fields mask, one per field of IntersectionRecord. */
    public static final int T = 1;
    public static final int LOCATION = 2;
    public static final int NORMAL = 4;
    public static final int SURFACE = 8;
    public static final int BETA = 16;
    public static final int GAMMA = 32;
    public static final int TEX_U = 64;
    public static final int TEX_V = 128;
    /** The bits of a ray's changed-fields mask: its segment. */
    public static final int START = 1;
    public static final int END = 2;

    private Records() {
    }

    public static void writeRay(WireOut out, Ray ray) {
        out.vec(ray.origin).vec(ray.direction).f64(ray.start).f64(ray.end);
    }

    public static Ray readRay(WireIn in) {
        Vec3 origin = in.vec();
        Vec3 direction = in.vec();
        return new Ray(origin, direction, in.f64(), in.f64());
    }

    /** A ray as a key: its origin, direction and start, seven numbers (its end is asked apart). */
    public static void writeKey(WireOut out, Ray ray) {
        out.f64(ray.origin.x).f64(ray.origin.y).f64(ray.origin.z).f64(ray.direction.x).f64(ray.direction.y).f64(ray.direction.z)
                .f64(ray.start);
    }

    /** A ray {@link #writeKey} wrote, with an endless segment. */
    public static Ray readKey(WireIn in) {
        Vec3 origin = new Vec3(in.f64(), in.f64(), in.f64());
        Vec3 direction = new Vec3(in.f64(), in.f64(), in.f64());
        return new Ray(origin, direction, in.f64(), Double.POSITIVE_INFINITY);
    }

    /** A ray, or null: a presence byte first. */
    public static void writeRayOrNull(WireOut out, Ray ray) {
        out.bool(ray != null);
        if (ray != null) {
            writeRay(out, ray);
        }
    }

    public static Ray readRayOrNull(WireIn in) {
        return in.bool() ? readRay(in) : null;
    }

    /**
     * A whole record: the mask of its fields that differ from a new record's (t = ∞, the rest null or
     * 0), then those fields. A new record, which most calls get, is one byte.
     */
    public static void write(WireOut out, IntersectionRecord r, Refs refs) {
        writeChanges(out, changes(FRESH, r), r, refs);
    }

    /** Sets every field of {@code into}: a new record's, then those the message gives. */
    public static void read(WireIn in, IntersectionRecord into, Refs refs) {
        into.set(FRESH);
        readChanges(in, into, refs);
    }

    /** A new record's values, which {@link #write} leaves out. */
    private static final IntersectionRecord FRESH = new IntersectionRecord();

    /** The fields of {@code after} that are not what {@code before} holds: doubles by their bits, objects by identity. */
    public static int changes(IntersectionRecord before, IntersectionRecord after) {
        int mask = 0;
        mask |= differ(before.t, after.t) ? T : 0;
        mask |= before.location != after.location ? LOCATION : 0;
        mask |= before.normal != after.normal ? NORMAL : 0;
        mask |= before.surface != after.surface ? SURFACE : 0;
        mask |= differ(before.beta, after.beta) ? BETA : 0;
        mask |= differ(before.gamma, after.gamma) ? GAMMA : 0;
        mask |= differ(before.texU, after.texU) ? TEX_U : 0;
        mask |= differ(before.texV, after.texV) ? TEX_V : 0;
        return mask;
    }

    private static boolean differ(double a, double b) {
        return Double.doubleToRawLongBits(a) != Double.doubleToRawLongBits(b);
    }

    /** The mask, then each field it names, of {@code after}. */
    public static void writeChanges(WireOut out, int mask, IntersectionRecord after, Refs refs) {
        out.u8(mask);
        if ((mask & T) != 0) {
            out.f64(after.t);
        }
        if ((mask & LOCATION) != 0) {
            out.vec(after.location);
        }
        if ((mask & NORMAL) != 0) {
            out.vec(after.normal);
        }
        if ((mask & SURFACE) != 0) {
            refs.writeSurface(out, after.surface);
        }
        if ((mask & BETA) != 0) {
            out.f64(after.beta);
        }
        if ((mask & GAMMA) != 0) {
            out.f64(after.gamma);
        }
        if ((mask & TEX_U) != 0) {
            out.f64(after.texU);
        }
        if ((mask & TEX_V) != 0) {
            out.f64(after.texV);
        }
    }

    /**
     * Reads what {@link #writeChanges} wrote into {@code changed}, a record whose other fields are
     * left as they are, and returns the mask.
     */
    public static int readChanges(WireIn in, IntersectionRecord changed, Refs refs) {
        int mask = in.u8();
        if ((mask & T) != 0) {
            changed.t = in.f64();
        }
        if ((mask & LOCATION) != 0) {
            changed.location = in.vec();
        }
        if ((mask & NORMAL) != 0) {
            changed.normal = in.vec();
        }
        if ((mask & SURFACE) != 0) {
            changed.surface = refs.readSurface(in);
        }
        if ((mask & BETA) != 0) {
            changed.beta = in.f64();
        }
        if ((mask & GAMMA) != 0) {
            changed.gamma = in.f64();
        }
        if ((mask & TEX_U) != 0) {
            changed.texU = in.f64();
        }
        if ((mask & TEX_V) != 0) {
            changed.texV = in.f64();
        }
        return mask;
    }

    /** Copies the fields {@code mask} names from {@code from} into {@code into}. */
    public static void apply(int mask, IntersectionRecord from, IntersectionRecord into) {
        if ((mask & T) != 0) {
            into.t = from.t;
        }
        if ((mask & LOCATION) != 0) {
            into.location = from.location;
        }
        if ((mask & NORMAL) != 0) {
            into.normal = from.normal;
        }
        if ((mask & SURFACE) != 0) {
            into.surface = from.surface;
        }
        if ((mask & BETA) != 0) {
            into.beta = from.beta;
        }
        if ((mask & GAMMA) != 0) {
            into.gamma = from.gamma;
        }
        if ((mask & TEX_U) != 0) {
            into.texU = from.texU;
        }
        if ((mask & TEX_V) != 0) {
            into.texV = from.texV;
        }
    }

    /** The segment's ends that the call changed (the ray's origin and direction are final). */
    public static int rayChanges(double startBefore, double endBefore, Ray after) {
        return (differ(startBefore, after.start) ? START : 0) | (differ(endBefore, after.end) ? END : 0);
    }

    public static void writeRayChanges(WireOut out, int mask, Ray after) {
        out.u8(mask);
        if ((mask & START) != 0) {
            out.f64(after.start);
        }
        if ((mask & END) != 0) {
            out.f64(after.end);
        }
    }

    public static int readRayChanges(WireIn in, Ray into) {
        int mask = in.u8();
        if ((mask & ~(START | END)) != 0) {
            throw new WireError("a ray's changed-fields mask of " + mask);
        }
        if ((mask & START) != 0) {
            into.start = in.f64();
        }
        if ((mask & END) != 0) {
            into.end = in.f64();
        }
        return mask;
    }
}
