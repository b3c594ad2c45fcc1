package ray.shading;

import java.util.Locale;

/**
 * The course conventions a scene is shaded by. The course changed its shading between its 2017 and
 * 2019 versions of Ray 1, and each version's reference images follow its own rules:
 *
 * <ul>
 * <li>{@link #Y2017}: each shader has its own formula: Lambertian kd·I·max(0, n·l)/r², Blinn–Phong
 * adds ks·I·max(0, n·h)^p/r² (not weighted by n·l); no mirror term, no back-face rule.
 * <li>{@link #Y2019}: every shader is a BRDF f, L = Σ f(l, v) ⊙ I · max(0, n·l)/r², with Lambertian
 * f = ρd/π and the course's "modified Blinn–Phong" f = ρd/π + ks·max(0, n·h)^p (so its highlight is
 * weighted by n·l too, and not normalised); a hit seen from behind its shading normal (n·v ≤ 0) is
 * black; {@code <mirrorCoefficient>} k_m adds a mirror ray weighted by Schlick's
 * k_m + (1 − k_m)(1 − n·v)^5; a path has at most {@link #MAX_PATH_HITS_2019} surface hits; and a
 * Lambertian without a {@code <diffuseColor>} is 0.2 gray.
 * </ul>
 *
 * The 2019 rules were checked pixel by pixel against that version's reference renders; ray1's own
 * scenes under {@code scenes-2019/} and their tests pin them.
 */
public enum Course {
    Y2017("2017"),
    Y2019("2019");

    /** In 2019, a camera ray's hit is the first of at most this many along a path of mirror rays. */
    public static final int MAX_PATH_HITS_2019 = 12;

    /**
     * The depth from which the course's tracer returns black, untraced (camera rays have depth 0):
     * under 2019's conventions a path has at most {@link #MAX_PATH_HITS_2019} hits; 2017's has no
     * such limit ({@link Integer#MAX_VALUE}: a glaze stops its own mirror rays).
     */
    public int maxRayDepth() {
        return this == Y2019 ? MAX_PATH_HITS_2019 : Integer.MAX_VALUE;
    }

    /** The year, as the assignment file and {@code --course} write it. */
    public final String year;

    Course(String year) {
        this.year = year;
    }

    /** The course of {@code year} ("2017" or "2019"); anything else is refused with a message naming both. */
    public static Course of(String year) {
        for (Course c : values()) {
            if (c.year.equals(year.trim().toLowerCase(Locale.ROOT))) {
                return c;
            }
        }
        throw new IllegalArgumentException("course " + year.trim() + " is not one ray1 knows; expected " + years());
    }

    /** "2017 or 2019". */
    public static String years() {
        StringBuilder s = new StringBuilder();
        Course[] all = values();
        for (int i = 0; i < all.length; i++) {
            s.append(i == 0 ? "" : i == all.length - 1 ? " or " : ", ").append(all[i].year);
        }
        return s.toString();
    }

    @Override
    public String toString() {
        return year;
    }
}
