package ray.testing;

/**
 * The parts of the assignment a student fills in. Each is a set of methods marked
 * {@code // TODO(Task N)} in the files listed here; tests carry {@link Points} for one task.
 */
public enum StudentTask {
    CAMERA(1, "Camera rays", "src/main/java/ray/camera/PerspectiveCamera.java", "src/main/java/ray/camera/OrthographicCamera.java"),
    SPHERE(2, "Sphere", "src/main/java/ray/surface/Sphere.java"),
    TRIANGLE(3, "Triangle", "src/main/java/ray/surface/Triangle.java"),
    GROUP(4, "Group", "src/main/java/ray/surface/Group.java"),
    TEXTURE(5, "Textures", "src/main/java/ray/shading/RepeatTexture.java", "src/main/java/ray/shading/ClampTexture.java"),
    /** Extra credit: every test of it is a bonus test. */
    CYLINDER(6, "Cylinder", "src/main/java/ray/surface/Cylinder.java");

    public final int number;
    public final String title;
    /** The files the student edits for this task, relative to the project folder. */
    public final java.util.List<String> files;

    StudentTask(int number, String title, String... files) {
        this.number = number;
        this.title = title;
        this.files = java.util.List.of(files);
    }

    /** "Task 2 (Sphere)". */
    public String label() {
        return "Task " + number + " (" + title + ")";
    }
}
