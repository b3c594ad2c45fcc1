package ray.accuracy;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import ray.scene.Scene;
import ray.scene.SceneLoader;

/** A small lit scene with edges for the accuracy tests: a sphere over a two-triangle floor, 48×36 pixels. */
final class SmallScenes {
    static final String SPHERE_ON_FLOOR = "<scene>\n"
            + "  <camera type=\"PerspectiveCamera\"><viewPoint>0 1 6</viewPoint><viewDir>0 -0.15 -1</viewDir>"
            + "<viewUp>0 1 0</viewUp><projDistance>2</projDistance><viewWidth>1.2</viewWidth><viewHeight>0.9</viewHeight></camera>\n"
            + "  <image>48 36</image>\n"
            + "  <light><position>3 5 4</position><intensity>30 30 30</intensity></light>\n"
            + "  <surface type=\"Sphere\"><shader type=\"Lambertian\"><diffuseColor>0.8 0.3 0.2</diffuseColor></shader>"
            + "<center>0 0 0</center><radius>1</radius></surface>\n"
            + "  <surface type=\"Triangle\"><v0>-6 -1 -6</v0><v1>-6 -1 6</v1><v2>6 -1 6</v2></surface>\n"
            + "  <surface type=\"Triangle\"><v0>-6 -1 -6</v0><v1>6 -1 6</v1><v2>6 -1 -6</v2></surface>\n"
            + "</scene>\n";

    private SmallScenes() {
    }

    static Path write(Path file) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        Files.write(file, SPHERE_ON_FLOOR.getBytes(StandardCharsets.UTF_8));
        return file;
    }

    static Scene load(Path folder) throws IOException {
        return SceneLoader.load(write(folder.resolve("sphere-on-floor.xml")));
    }
}
