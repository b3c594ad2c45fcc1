package ray.scene;

import java.nio.file.Path;
import ray.assignment.Assignment;
import ray.shading.Course;

/**
 * How a scene file is read: the course conventions it renders by, and where its data paths (meshes,
 * texture images) start from.
 */
public final class SceneOptions {
    /** The course whose conventions the scene is shaded by. */
    public final Course course;
    /**
     * The folder every relative data path starts from, as the course's own renderer read them (its
     * scenes sit in sub-folders of one root and name data from there); null to start from the scene
     * file's folder and, for a file not there, from the nearest folder above it that has it.
     */
    public final Path sceneRoot;

    private SceneOptions(Course course, Path sceneRoot) {
        this.course = course;
        this.sceneRoot = sceneRoot == null ? null : sceneRoot.toAbsolutePath().normalize();
    }

    public static SceneOptions of(Course course, Path sceneRoot) {
        return new SceneOptions(course, sceneRoot);
    }

    /** The running assignment's course ({@code course} in assignment.properties), data beside the scene. */
    public static SceneOptions ofAssignment() {
        return new SceneOptions(Course.of(Assignment.current().course()), null);
    }

    /** {@code course}, or the assignment's when null, and {@code sceneRoot} (null: beside the scene). */
    public static SceneOptions orAssignment(Course course, Path sceneRoot) {
        return new SceneOptions(course != null ? course : Course.of(Assignment.current().course()), sceneRoot);
    }
}
