package ray.scene;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.ImageIO;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.image.Image;
import ray.shading.ClampTexture;
import ray.shading.DirectLighting;
import ray.shading.Phong;
import ray.shading.RepeatTexture;
import ray.shading.Shader;
import ray.shading.Texture;

/**
 * Checks textures in the course's scene format: a named {@code <texture>} reused by ref and an
 * inline one, image paths relative to the scene file (with {@code ../}), texels as the file's 8-bit
 * values / 255 counted from the bottom row, and a located one-line error for every way an image can
 * fail: missing, a folder, unreadable, empty, not an image, damaged, too large, or not given.
 * Reads no texel through the student's lookups, so it runs the same before and after Task 5.
 */
public class SceneLoaderTexturesTest {
    private static final String FORMATS = "expected a PNG, JPEG, GIF or BMP image";

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private Path root() {
        return folder.getRoot().toPath();
    }

    /**
     * A 3×2 PNG at {@code relativePath} whose pixel (x, y), y from the top as the file stores it,
     * has the 8-bit color (100·x + 1, 50·y + 2, 3).
     */
    private Path writeDistinctPng(String relativePath) {
        BufferedImage image = new BufferedImage(3, 2, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 3; x++) {
                image.setRGB(x, y, (100 * x + 1) << 16 | (50 * y + 2) << 8 | 3);
            }
        }
        return writePng(relativePath, image);
    }

    private Path writePng(String relativePath, BufferedImage image) {
        try {
            Path file = root().resolve(relativePath);
            Files.createDirectories(file.getParent());
            ImageIO.write(image, "png", file.toFile());
            return file;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** scenes/scene.xml: a named texture of {@code image} (line 5 holds its {@code <image>}, column 12) and a sphere using it. */
    private Path sceneWithTexture(String image) {
        return SceneFixtures.write(folder, "scenes/scene.xml", "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE
                + "  <texture type=\"RepeatTexture\" name=\"tex\">\n"
                + "    <image>" + image + "</image>\n"
                + "  </texture>\n"
                + "  <surface type=\"Sphere\">\n"
                + "    <shader type=\"Lambertian\"><texture ref=\"tex\"/></shader>\n"
                + "  </surface>\n"
                + "</scene>\n");
    }

    private static Texture textureOf(Shader shader) {
        assertTrue(shader + " is a lit shader", shader instanceof DirectLighting);
        Texture texture = ((DirectLighting) shader).getTexture();
        assertNotNull(shader + " has a texture", texture);
        return texture;
    }

    @Test
    public void namedTextureIsSharedByRefAndItsPathStartsFromTheScenesFolder() {
        writeDistinctPng("textures/t.png");
        Scene scene = SceneLoader.load(SceneFixtures.write(folder, "scenes/scene.xml", "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE
                + "  <texture type=\"RepeatTexture\" name=\"tex\"><image>../textures/t.png</image></texture>\n"
                + "  <shader type=\"Lambertian\" name=\"matte\"><texture ref=\"tex\"/></shader>\n"
                + "  <shader type=\"Phong\" name=\"shiny\"><texture ref=\"tex\"/><exponent>10</exponent></shader>\n"
                + "</scene>\n"));
        assertEquals(1, scene.getTextures().size());
        Texture texture = scene.getTextures().get(0);
        assertTrue(texture instanceof RepeatTexture);
        assertSame(texture, textureOf(scene.getShaders().get(0)));
        assertSame(texture, textureOf(scene.getShaders().get(1)));
        assertEquals(10, ((Phong) scene.getShaders().get(1)).getExponent(), 0);
        Image texels = texture.getImage();
        assertEquals(3, texels.width());
        assertEquals(2, texels.height());
        // Texel (i, j) counts j from the bottom: j = 0 is the file's row y = 1.
        assertVec("texel (0, 0)", v(1 / 255.0, 52 / 255.0, 3 / 255.0), texels.get(0, 0), 0);
        assertVec("texel (2, 0)", v(201 / 255.0, 52 / 255.0, 3 / 255.0), texels.get(2, 0), 0);
        assertVec("texel (1, 1)", v(101 / 255.0, 2 / 255.0, 3 / 255.0), texels.get(1, 1), 0);
    }

    @Test
    public void inlineTexturesSitInLambertianAndPhongShaders() {
        writeDistinctPng("t.png");
        Scene scene = SceneFixtures.loadBody(folder, ""
                + "  <shader type=\"Lambertian\" name=\"a\"><texture type=\"ClampTexture\"><image>t.png</image></texture></shader>\n"
                + "  <shader type=\"Phong\" name=\"b\">\n"
                + "    <texture type=\"RepeatTexture\"><image>t.png</image></texture>\n"
                + "    <specularColor>0.9 0.7 0.3</specularColor>\n"
                + "  </shader>\n");
        assertTrue(textureOf(scene.getShaders().get(0)) instanceof ClampTexture);
        assertTrue(textureOf(scene.getShaders().get(1)) instanceof RepeatTexture);
        assertVec(v(0.9, 0.7, 0.3), ((Phong) scene.getShaders().get(1)).getSpecularColor(), 0);
        assertVec("the two read the same file", textureOf(scene.getShaders().get(0)).getImage().get(2, 1),
                textureOf(scene.getShaders().get(1)).getImage().get(2, 1), 0);
    }

    /** A gray PNG's texel is its stored level / 255 in every channel, not a color-space conversion of it. */
    @Test
    public void grayImageTexelsAreTheirStoredLevels() {
        BufferedImage gray = new BufferedImage(2, 1, BufferedImage.TYPE_BYTE_GRAY);
        gray.getRaster().setSample(0, 0, 0, 128);
        gray.getRaster().setSample(1, 0, 0, 7);
        writePng("scenes/gray.png", gray);
        Scene scene = SceneLoader.load(sceneWithTexture("gray.png"));
        Image texels = scene.getTextures().get(0).getImage();
        assertVec(v(128 / 255.0, 128 / 255.0, 128 / 255.0), texels.get(0, 0), 0);
        assertVec(v(7 / 255.0, 7 / 255.0, 7 / 255.0), texels.get(1, 0), 0);
    }

    private void assertImageError(String image, String problem) {
        Path scene = sceneWithTexture(image);
        SceneFixtures.assertError(SceneFixtures.loadError(scene), scene, 5, 12, problem);
    }

    @Test
    public void missingImageNamesTheResolvedPath() {
        assertImageError("../textures/none.png", "image file " + root().resolve("textures/none.png") + " does not exist; "
                + FORMATS + " (a relative path starts from the scene file's folder)");
    }

    @Test
    public void folderIsNotAnImage() {
        SceneFixtures.write(folder, "textures/dir.png/inside", new byte[1]);
        assertImageError("../textures/dir.png", "image path " + root().resolve("textures/dir.png") + " is not a regular file; " + FORMATS);
    }

    @Test
    public void unreadableImageSaysWhy() {
        Path file = writeDistinctPng("textures/locked.png");
        String reason = SceneFixtures.makeUnreadable(file);
        assertImageError("../textures/locked.png", "image file " + file + " cannot be read (" + reason + "); expected a readable image file");
    }

    @Test
    public void emptyOrTextFileIsNotAnImage() {
        SceneFixtures.write(folder, "textures/empty.png", new byte[0]);
        assertImageError("../textures/empty.png", "image file " + root().resolve("textures/empty.png") + " is empty; " + FORMATS);
        SceneFixtures.write(folder, "textures/text.png", "hello");
        assertImageError("../textures/text.png", "image file " + root().resolve("textures/text.png")
                + " is not an image this program can read; " + FORMATS);
    }

    @Test
    public void truncatedPngIsDamaged() throws IOException {
        Path whole = writeDistinctPng("textures/whole.png");
        byte[] bytes = Files.readAllBytes(whole);
        Path cut = SceneFixtures.write(folder, "textures/cut.png", Arrays.copyOf(bytes, 40));
        Path scene = sceneWithTexture("../textures/cut.png");
        String message = SceneFixtures.loadError(scene).getMessage();
        assertTrue(message, message.startsWith(scene + ":5:12: image file " + cut + " is damaged or unreadable ("));
        assertTrue(message, message.endsWith("); " + FORMATS));
        assertTrue(message, !message.contains("\n"));
    }

    /** The size is read from the header, so an image one texel too wide is refused before its texels are decoded. */
    @Test
    public void imageWiderThanTheLimitIsTooLarge() {
        Path wide = writePng("textures/wide.png", new BufferedImage(8193, 1, BufferedImage.TYPE_INT_RGB));
        assertImageError("../textures/wide.png", "image file " + wide + " is 8193×1, too large for a texture;"
                + " expected at most 8192 texels a side and 16777216 in all");
    }

    @Test
    public void textureWithoutAnImageSaysWhatIsMissing() {
        SceneException e = SceneFixtures.loadError(folder, "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE
                + "  <texture type=\"ClampTexture\" name=\"tex\"/>\n</scene>\n");
        SceneFixtures.assertError(e, root().resolve("bad.xml"), 4, 44,
                "invalid ClampTexture: no <image> is given; expected <image> with the path of an image file");
    }

    @Test
    public void misspelledRefAndTypeSuggestTheName() {
        writeDistinctPng("t.png");
        SceneException ref = SceneFixtures.loadError(folder, "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE
                + "  <texture type=\"ClampTexture\" name=\"earthTex\"><image>t.png</image></texture>\n"
                + "  <shader type=\"Phong\" name=\"s\"><texture ref=\"earthTx\"/></shader>\n</scene>\n");
        SceneFixtures.assertError(ref, root().resolve("bad.xml"), 5, 57,
                "unknown ref \"earthTx\" (did you mean \"earthTex\"?); expected the name of a Texture defined earlier in the file");
        SceneException type = SceneFixtures.loadError(folder, "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE
                + "  <texture type=\"RepeatTextur\" name=\"earthTex\"><image>t.png</image></texture>\n</scene>\n");
        SceneFixtures.assertError(type, root().resolve("bad.xml"), 4, 48,
                "unknown type \"RepeatTextur\" for <texture> (did you mean \"RepeatTexture\"?); expected one of RepeatTexture, ClampTexture");
    }

    /** RGBNormals colors by the normal alone: it has no properties, so a texture in it is an error that says so. */
    @Test
    public void textureInAShaderWithoutPropertiesIsRefused() {
        SceneException e = SceneFixtures.loadError(folder, "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE
                + "  <shader type=\"RGBNormals\" name=\"n\">\n    <texture ref=\"x\"/>\n  </shader>\n</scene>\n");
        SceneFixtures.assertError(e, root().resolve("bad.xml"), 5, 23,
                "unknown element <texture> in a RGBNormals; expected no elements inside it (it has no properties)");
    }
}
