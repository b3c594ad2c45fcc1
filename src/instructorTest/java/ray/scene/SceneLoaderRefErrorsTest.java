package ray.scene;

import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * Checks what a ref that names nothing suggests, for every kind of object a ref can name (shader,
 * substrate, texture, surface, light): the closest defined name of that kind as "did you mean", else
 * the names of that kind, else that none is defined. Names of other kinds are never offered: they
 * would only lead to "names a …; expected a …". Each error is checked whole, as in
 * {@link SceneLoaderNameErrorsTest}; the scene's body starts on line 4, after the camera and image.
 */
public class SceneLoaderRefErrorsTest {
    private static final String SHADER_BLUE = "  <shader name=\"blue\" type=\"Lambertian\"/>\n";

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void misspelledRefSuggestsADefinedName() {
        // "    <shader ref=\"blu\"/>" ends in column 23: SAX places the element just after it.
        SceneFixtures.assertError(bodyError(SHADER_BLUE + sphereWithShaderRef("blu")), bad(), 6, 24,
                "unknown ref \"blu\" (did you mean \"blue\"?); expected the name of a Shader defined earlier in the file");
    }

    @Test
    public void wronglyCasedRefSuggestsTheDefinedName() {
        SceneFixtures.assertError(bodyError(SHADER_BLUE + sphereWithShaderRef("Blue")), bad(), 6, 25,
                "unknown ref \"Blue\" (did you mean \"blue\"?); expected the name of a Shader defined earlier in the file");
    }

    @Test
    public void swappedLettersSuggestTheDefinedName() {
        SceneFixtures.assertError(bodyError(SHADER_BLUE + sphereWithShaderRef("bleu")), bad(), 6, 25,
                "unknown ref \"bleu\" (did you mean \"blue\"?); expected the name of a Shader defined earlier in the file");
    }

    @Test
    public void aCloseNameOfAnotherKindIsNotSuggested() {
        SceneException e = bodyError("""
                  <shader name="red" type="Lambertian"/>
                  <surface type="Sphere" name="blue">
                    <shader ref="red"/>
                  </surface>
                """ + sphereWithShaderRef("bleu"));
        SceneFixtures.assertError(e, bad(), 9, 25, "unknown ref \"bleu\"; expected \"red\", the only Shader defined earlier in the file");
    }

    @Test
    public void aFarNameListsTheNamesOfItsKind() {
        SceneException e = bodyError("""
                  <shader name="red" type="Lambertian"/>
                  <shader name="green" type="Lambertian"/>
                  <shader name="blue" type="Phong"/>
                """ + sphereWithShaderRef("purple"));
        SceneFixtures.assertError(e, bad(), 8, 27,
                "unknown ref \"purple\"; expected one of the Shaders defined earlier in the file: \"blue\", \"green\", \"red\"");
    }

    @Test
    public void manyNamesAreListedUpToTen() {
        StringBuilder shaders = new StringBuilder();
        for (int i = 1; i <= 12; i++) {
            shaders.append(String.format("  <shader name=\"s%02d\" type=\"Lambertian\"/>\n", i));
        }
        SceneFixtures.assertError(bodyError(shaders + sphereWithShaderRef("purple")), bad(), 17, 27,
                "unknown ref \"purple\"; expected one of the Shaders defined earlier in the file: \"s01\", \"s02\", \"s03\","
                        + " \"s04\", \"s05\", \"s06\", \"s07\", \"s08\", \"s09\", \"s10\" and 2 more");
    }

    @Test
    public void noNameOfTheKindSaysNoneIsDefined() {
        SceneException e = bodyError("""
                  <shader name="matte" type="Lambertian">
                    <texture ref="wood"/>
                  </shader>
                """);
        SceneFixtures.assertError(e, bad(), 5, 26,
                "unknown ref \"wood\"; expected the name of a Texture defined earlier in the file (none is defined before this ref)");
    }

    @Test
    public void surfaceRefInAGroupSuggestsASurface() {
        SceneException e = bodyError(SHADER_BLUE + """
                  <surface type="Sphere" name="ball">
                    <shader ref="blue"/>
                  </surface>
                  <surface type="Group">
                    <surface ref="bal"/>
                  </surface>
                """);
        SceneFixtures.assertError(e, bad(), 9, 25,
                "unknown ref \"bal\" (did you mean \"ball\"?); expected the name of a Surface defined earlier in the file");
    }

    @Test
    public void substrateRefSuggestsAShader() {
        SceneException e = bodyError("""
                  <shader name="matte" type="Phong"/>
                  <shader name="glaze" type="Glazed">
                    <substrate ref="mate"/>
                  </shader>
                """);
        SceneFixtures.assertError(e, bad(), 6, 28,
                "unknown ref \"mate\" (did you mean \"matte\"?); expected the name of a Shader defined earlier in the file");
    }

    @Test
    public void lightRefSuggestsALight() {
        SceneException e = bodyError("""
                  <light name="key">
                    <position>0 5 0</position>
                    <intensity>1 1 1</intensity>
                  </light>
                  <light ref="kye"/>
                """);
        SceneFixtures.assertError(e, bad(), 8, 21,
                "unknown ref \"kye\" (did you mean \"key\"?); expected the name of a Light defined earlier in the file");
    }

    /** Three lines: a sphere whose shader is {@code <shader ref="ref"/>}, on the second of them. */
    private static String sphereWithShaderRef(String ref) {
        return "  <surface type=\"Sphere\">\n    <shader ref=\"" + ref + "\"/>\n  </surface>\n";
    }

    /** The error of loading bad.xml: {@code <scene>}, a camera and an image size (lines 1 to 3), then {@code body}. */
    private SceneException bodyError(String body) {
        return SceneFixtures.loadError(folder, "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE + body + "</scene>\n");
    }

    private Path bad() {
        return folder.getRoot().toPath().resolve("bad.xml");
    }
}
