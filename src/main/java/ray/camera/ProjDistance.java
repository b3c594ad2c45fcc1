package ray.camera;

/**
 * A perspective camera's projDistance, read from its field: PerspectiveCamera.java is a student
 * file, and the grader compiles the framework against each student's copy of it, so the framework
 * may use nothing in it beyond what every handout has had (the field and its setter). A copy
 * without the field counts as a plane 1 unit away, the handout's default.
 */
public final class ProjDistance {
    private ProjDistance() {
    }

    public static double of(PerspectiveCamera camera) {
        try {
            java.lang.reflect.Field field = PerspectiveCamera.class.getDeclaredField("projDistance");
            field.setAccessible(true);
            return field.getDouble(camera);
        } catch (ReflectiveOperationException | RuntimeException e) {
            return 1;
        }
    }
}
