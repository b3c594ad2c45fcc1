package ray.cli;

/** The program's entry point: {@code ray1 render [options] SCENE.xml|DIR ...}; see {@link Ray1Command}. */
public final class Ray1 {
    private Ray1() {
    }

    public static void main(String[] args) {
        System.exit(Ray1Command.run(args));
    }
}
