package ray.inspect;

import java.util.Locale;
import ray.Ray;
import ray.math.Vec3;

/**
 * Numbers as a student reads them: six significant digits, no trailing zeros, whole numbers
 * without a decimal point, and the same output in every locale (Locale.ROOT).
 */
final class Fmt {
    private Fmt() {
    }

    static String num(double x) {
        if (Double.isNaN(x)) {
            return "NaN";
        }
        if (Double.isInfinite(x)) {
            return x > 0 ? "∞" : "−∞";
        }
        if (x == 0) {
            return "0";
        }
        if (x == Math.rint(x) && Math.abs(x) < 1e9) {
            return String.format(Locale.ROOT, "%d", (long) x);
        }
        double magnitude = Math.abs(x);
        return magnitude >= 1e-4 && magnitude < 1e9
                ? stripZeros(String.format(Locale.ROOT, "%.6g", x))
                : String.format(Locale.ROOT, "%.5e", x).replaceFirst("\\.?0+e", "e");
    }

    /** "12 triangles", "1 surface". */
    static String count(int n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }

    static String vec(Vec3 v) {
        return v == null ? "null" : v.format(Fmt::num);
    }

    static String ray(Ray ray) {
        return "origin " + vec(ray.origin) + ", direction " + vec(ray.direction)
                + ", t in (" + num(ray.start) + ", " + num(ray.end) + ")";
    }

    /** An 8-bit color as "(r, g, b)  #RRGGBB", the way image viewers show a pixel. */
    static String rgb8(int[] rgb) {
        return String.format(Locale.ROOT, "(%d, %d, %d)  #%02X%02X%02X", rgb[0], rgb[1], rgb[2], rgb[0], rgb[1], rgb[2]);
    }

    /** A label and its value, the labels padded to one column. */
    static String row(String indent, String label, String value) {
        return String.format(Locale.ROOT, "%s%-12s %s", indent, label, value);
    }

    private static String stripZeros(String s) {
        if (!s.contains(".") || s.contains("e")) {
            return s;
        }
        s = s.replaceFirst("0+$", "");
        return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
    }
}
