package ray.render;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.camera.PerspectiveCamera;
import ray.image.Image;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Glazed;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.shading.Phong;
import ray.surface.Sphere;

/** The image and the ray counts do not depend on the number of threads, down to every bit of every pixel. */
public class ThreadDeterminismTest {

    /** Spheres over a floor, with Lambertian, Phong and Glazed, shadows and two lights. */
    private static Scene busyScene() {
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewPoint(v(0, 1.5, 6));
        camera.setViewDir(v(0, -0.25, -1));
        camera.setProjDistance(1.5);
        camera.setViewWidth(1.2);
        camera.setViewHeight(0.85);
        camera.complete();
        Scene scene = TestScenes.scene(camera, 24, 17);
        scene.setBackColor(v(0.1, 0.2, 0.3));
        scene.addLight(new Light(v(3, 5, 4), v(30, 28, 25)));
        scene.addLight(new Light(v(-4, 3, 1), v(8, 10, 12)));
        scene.addSurface(TestScenes.plane(-1, true, new Lambertian(v(0.6, 0.6, 0.5))));
        Phong phong = new Phong();
        phong.setDiffuseColor(v(0.7, 0.2, 0.2));
        phong.setSpecularColor(v(0.5, 0.5, 0.5));
        phong.setExponent(40);
        Sphere red = new Sphere(v(-1.1, 0, 0), 1);
        red.setShader(phong);
        scene.addSurface(red.complete());
        Sphere glazed = new Sphere(v(1.1, 0, -0.5), 1);
        glazed.setShader(new Glazed());
        scene.addSurface(glazed.complete());
        scene.complete();
        return scene;
    }

    @Test
    public void imageIsBitIdenticalWithOneTwoAndEightThreads() {
        Scene scene = busyScene();
        RenderResult one = new Renderer(scene, 4, 1).render();
        assertEquals(1, one.threads);
        assertPictureIsNotTrivial(one.image, scene.getBackColor());
        assertTrue("the scene traces shadow rays", one.rays.shadow > 0);
        assertTrue("the scene traces reflection rays", one.rays.reflection > 0);
        for (int threads : new int[] {2, 8}) {
            RenderResult many = new Renderer(scene, 4, threads).render();
            assertEquals(threads, many.threads);
            for (int j = 0; j < 17; j++) {
                for (int i = 0; i < 24; i++) {
                    Vec3 a = one.image.get(i, j);
                    Vec3 b = many.image.get(i, j);
                    String where = "pixel (" + i + ", " + j + ") with " + threads + " threads";
                    assertEquals(where, Double.doubleToRawLongBits(a.x), Double.doubleToRawLongBits(b.x));
                    assertEquals(where, Double.doubleToRawLongBits(a.y), Double.doubleToRawLongBits(b.y));
                    assertEquals(where, Double.doubleToRawLongBits(a.z), Double.doubleToRawLongBits(b.z));
                }
            }
            assertEquals(one.rays.camera, many.rays.camera);
            assertEquals(one.rays.shadow, many.rays.shadow);
            assertEquals(one.rays.reflection, many.rays.reflection);
        }
    }

    @Test
    public void moreThreadsThanRowsUsesOneThreadPerRow() {
        RenderResult result = new Renderer(busyScene(), 1, 64).render();
        assertEquals(17, result.threads);
        assertEquals(24 * 17, result.rays.camera);
    }

    /** Guards against comparing two blank images: the scene must show hits, shadows and reflections. */
    private static void assertPictureIsNotTrivial(Image image, Vec3 backColor) {
        int background = 0;
        int distinct = 0;
        Vec3 previous = null;
        for (int j = 0; j < image.height(); j++) {
            for (int i = 0; i < image.width(); i++) {
                Vec3 c = image.get(i, j);
                if (c.equals(backColor)) {
                    background++;
                }
                if (!c.equals(previous)) {
                    distinct++;
                }
                previous = c;
            }
        }
        assertTrue("some pixels show surfaces", background < image.width() * image.height() / 2);
        assertTrue("pixels vary", distinct > image.width() * image.height() / 2);
    }
}
