package ray.scene;

import java.nio.file.Path;
import java.util.function.UnaryOperator;
import ray.assignment.Assignment;
import ray.shading.Brdf;
import ray.shading.Course;
import ray.shading.MicrofacetFactor;

/**
 * How a scene file is read: the course conventions it renders by, where its data paths (meshes,
 * texture images) start from, and whether its microfacet shaders show one factor alone.
 *
 * <p>When no course is given, a scene shipped with ray1 renders by the conventions of its folder
 * ({@link #SCENES_2019} holds 2019's scenes, {@link #SCENES_2017} 2017's), so its render matches its
 * reference whatever the assignment's course; any other scene renders by the assignment's.
 */
public final class SceneOptions {
    /** The folder of ray1's scenes in the course's 2017 conventions (and a student's own scenes beside them). */
    public static final String SCENES_2017 = "scenes";
    /** The folder of ray1's scenes in the course's 2019 conventions. */
    public static final String SCENES_2019 = "scenes-2019";

    /** The course whose conventions the scene is shaded by. */
    public final Course course;
    /** Whether {@link #course} was asked for ({@code --course}, or by a caller), rather than taken from the assignment. */
    private final boolean courseGiven;
    /**
     * The folder every relative data path starts from, as the course's own renderer read them (its
     * scenes sit in sub-folders of one root and name data from there); null to start from the scene
     * file's folder and, for a file not there, from the nearest folder above it that has it.
     */
    public final Path sceneRoot;
    /** The one factor every microfacet shader shows in place of its BRDF (the debug views), or null for the whole BRDF. */
    public final MicrofacetFactor microfacetFactor;
    /**
     * What every 2019 shader's BRDF is replaced by, given the BRDF the scene made (an approximation
     * whose cost the accuracy study measures), or null to keep them.
     */
    public final UnaryOperator<Brdf> brdfs;

    private SceneOptions(Course course, boolean courseGiven, Path sceneRoot, MicrofacetFactor microfacetFactor, UnaryOperator<Brdf> brdfs) {
        this.course = course;
        this.courseGiven = courseGiven;
        this.sceneRoot = sceneRoot == null ? null : sceneRoot.toAbsolutePath().normalize();
        this.microfacetFactor = microfacetFactor;
        this.brdfs = brdfs;
    }

    private SceneOptions(Course course, boolean courseGiven, Path sceneRoot) {
        this(course, courseGiven, sceneRoot, null, null);
    }

    /** These options with every microfacet shader showing {@code factor} alone (null: the whole BRDF). */
    public SceneOptions withMicrofacetFactor(MicrofacetFactor factor) {
        return new SceneOptions(course, courseGiven, sceneRoot, factor, brdfs);
    }

    /** These options with every 2019 shader's BRDF replaced by what {@code replace} makes of it (null: kept). */
    public SceneOptions withBrdfs(UnaryOperator<Brdf> replace) {
        return new SceneOptions(course, courseGiven, sceneRoot, microfacetFactor, replace);
    }

    public static SceneOptions of(Course course, Path sceneRoot) {
        return new SceneOptions(course, true, sceneRoot);
    }

    /** The running assignment's course ({@code course} in assignment.properties), data beside the scene. */
    public static SceneOptions ofAssignment() {
        return new SceneOptions(Course.of(Assignment.current().course()), false, null);
    }

    /** {@code course}, or the assignment's when null, and {@code sceneRoot} (null: beside the scene). */
    public static SceneOptions orAssignment(Course course, Path sceneRoot) {
        return new SceneOptions(course != null ? course : Course.of(Assignment.current().course()), course != null, sceneRoot);
    }

    /**
     * These options for the scene file {@code file}: as they are when the course was given; else, for
     * a file in one of ray1's scene folders, that folder's course (the nearest such folder above it).
     */
    public SceneOptions forFile(Path file) {
        if (courseGiven) {
            return this;
        }
        Course shipped = courseOfFolder(file);
        return shipped == null || shipped == course ? this : new SceneOptions(shipped, false, sceneRoot, microfacetFactor, brdfs);
    }

    /** The course of the nearest folder above {@code file} named {@link #SCENES_2017} or {@link #SCENES_2019}, or null. */
    public static Course courseOfFolder(Path file) {
        for (Path p = file.toAbsolutePath().normalize().getParent(); p != null && p.getFileName() != null; p = p.getParent()) {
            String name = p.getFileName().toString();
            if (name.equals(SCENES_2019)) {
                return Course.Y2019;
            }
            if (name.equals(SCENES_2017)) {
                return Course.Y2017;
            }
        }
        return null;
    }
}
