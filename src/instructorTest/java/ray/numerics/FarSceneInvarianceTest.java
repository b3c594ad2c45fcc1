package ray.numerics;

import static org.junit.Assert.assertTrue;

import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;
import ray.image.ImageDiff;
import ray.math.Vec3;

/**
 * A scene renders the same wherever it sits and whatever its size: boxes on a slab (two-boxes),
 * spheres, boxes and a mesh with reflections (glazed-sphere) and a smooth mesh resting on the
 * ground (mesh-smooth), all with contact shadows, written 10⁶, 10⁹, 3·10¹¹ and 10¹² from the origin
 * ({@link FarScenes}: every position in its own numbers) or scaled by 10⁻⁴ and 10⁴
 * ({@link MovedScenes}), render at half size within 0.05% of the pixels of the unmoved render
 * (more than 2 levels off). Measured ({@link FarSceneSurvey}): at most 5 pixels of 19,200 (0.03%,
 * glazed-sphere at 10¹²), 0 in 14 of the 18 cases.
 *
 * <p>It is the camera's frame that holds them: rendered in their own coordinates, as before, the
 * same scenes lose 1.3–4.9% of their pixels at 10¹² (shadow edges and silhouettes), which
 * {@link #theSceneOwnCoordinatesDoNotHoldAtATrillion} keeps in view.
 */
@RunWith(Parameterized.class)
public class FarSceneInvarianceTest {
    private static final int SHRINK = 2;
    private static final double ALLOWED_SHARE = 0.0005;
    private static final Map<String, BufferedImage> ORIGINALS = new ConcurrentHashMap<>();

    @Parameters(name = "{0} {1}")
    public static List<Object[]> cases() {
        List<Object[]> list = new ArrayList<>();
        for (String scene : new String[] {"two-boxes", "glazed-sphere", "mesh-smooth"}) {
            for (String move : new String[] {"moved 1e6", "moved 1e9", "moved 3e11", "moved 1e12", "scaled 1e-4", "scaled 1e4"}) {
                list.add(new Object[] {scene, move});
            }
        }
        return list;
    }

    private final String scene;
    private final String move;

    public FarSceneInvarianceTest(String scene, String move) {
        this.scene = scene;
        this.move = move;
    }

    private BufferedImage original() {
        return ORIGINALS.computeIfAbsent(scene, s -> FarScenes.render(FarScenes.load(s, Vec3.ZERO, SHRINK)));
    }

    private ray.scene.Scene moved() {
        double amount = Double.parseDouble(move.substring(move.indexOf(' ') + 1));
        return move.startsWith("moved")
                ? FarScenes.load(scene, new Vec3(amount, amount, amount), SHRINK)
                : MovedScenes.load(scene, amount, Vec3.ZERO, SHRINK);
    }

    @Test
    public void rendersLikeTheOriginal() {
        ImageDiff.Result result = ImageDiff.compare(original(), FarScenes.render(moved()));
        assertTrue(scene + " " + move + ": " + result.summary(), result.differingShare() <= ALLOWED_SHARE);
    }

    /** The comparison can fail: in the scene's own coordinates, 10¹² away, shadow edges and silhouettes move. */
    @Test
    public void theSceneOwnCoordinatesDoNotHoldAtATrillion() {
        if (!move.equals("moved 1e12")) {
            return;
        }
        ImageDiff.Result result = ImageDiff.compare(original(), FarScenes.renderInWorldFrame(moved()));
        assertTrue(scene + " in its own coordinates at 1e12 should lose more than 1% of its pixels: " + result.summary(),
                result.differingShare() > 0.01);
    }
}
