package ray.scene;

import java.nio.file.Path;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;

/**
 * Checks the errors of scene files, one row of the table per case: the scene's text (written to
 * bad.xml), and the line, column and message of the error that loading it must raise. Each error is
 * checked whole: the file, line and column, what is wrong and what was expected (SceneFixtures.assertError).
 * The rows come in four groups:
 * <ul>
 * <li>Names: unknown elements, types and attributes (with a "did you mean" when a known name is
 * close), a missing type, refs that name something later, the object they are in or the wrong kind
 * of object, and a name used twice.
 * <li>References: what a ref that names nothing suggests, for every kind of object a ref can name
 * (shader, substrate, texture, surface, light): the closest defined name of that kind as "did you
 * mean", else the names of that kind, else that none is defined. Names of other kinds are never
 * offered: they would only lead to "names a …; expected a …".
 * <li>Values: the wrong number of values, words and special values where numbers belong, fractions
 * where integers belong, values out of range (radius, image size, samples, exposure, view size,
 * projection distance, camera axes, scale), a mesh without its file, and a scene without a camera or
 * an image size. (Box corners in either order load, with a warning: SceneLoaderWarningsTest.)
 * <li>XML: malformed markup, the wrong root, text where elements belong, and a file that is empty or
 * holds no element.
 * </ul>
 * Cases that need more than one scene text, or check more than its error (mesh files that are
 * missing, folders, empty, unreadable or broken, a transform that cannot be inverted, scene files
 * that are missing, folders, unreadable or not UTF-8, and the refusal of any DOCTYPE, so that no
 * entity can expand without bound or read a local file) are in {@link SceneLoaderErrorsSpecialTest}.
 *
 * <p>SAX locates an element where its start tag ends, so an element's column is the one just after
 * its {@code >} (for {@code "    <radius>"}, column 13); each element sits on its own line so that
 * the line is unambiguous. Most scenes are built by {@link #body} (a camera and an image size on lines
 * 2 and 3, the body from line 4) or {@link #sphere} (a sphere from line 4, its one property on line 5).
 */
@RunWith(Parameterized.class)
public class SceneLoaderErrorsTest {
    private static final String SURFACE_TYPES = "Sphere, Triangle, Box, Mesh, Cylinder, Group";
    private static final String SHADER_TYPES = "Lambertian, Phong, MicrofacetBeckmann, MicrofacetGGX, Microfacet, RGBNormals, Glazed";
    private static final String THREE_CENTER_NUMBERS = "three numbers, e.g. <center>1 0 -2.5</center>";
    private static final String SHADER_BLUE = "  <shader name=\"blue\" type=\"Lambertian\"/>\n";

    @Parameters(name = "{0}")
    public static List<Object[]> cases() {
        return List.of(
                // ---- Names: unknown elements, types and attributes, a missing type, refs that name
                // something later, the object they are in or the wrong kind of object, a name used twice.
                row("misspelled property suggests the closest one", sphere("    <radus>1</radus>\n"), 5, 12,
                        "unknown element <radus> in a Sphere (did you mean <radius>?); expected one of center, radius, rotate, scale, shader, translate"),
                row("unknown element far from any name lists the expected ones", body("  <sphere/>\n"), 4, 12,
                        "unknown element <sphere> in <scene>;"
                                + " expected one of backColor, brdf, camera, exposure, image, light, samples, shader, surface, texture"),
                row("property of the other camera type is unknown", camera("OrthographicCamera", "<projDistance>2</projDistance>"), 3, 19, "unknown element <projDistance> in an OrthographicCamera;"
                                + " expected one of viewDir, viewHeight, viewPoint, viewUp, viewWidth"),
                row("misspelled type suggests the closest one", body("""
                          <surface type="Sphre">
                          </surface>
                        """), 4, 25,
                        "unknown type \"Sphre\" for <surface> (did you mean \"Sphere\"?); expected one of " + SURFACE_TYPES),
                row("wrongly cased type suggests the right case", body("""
                          <shader name="a" type="lambertian"/>
                        """), 4, 39,
                        "unknown type \"lambertian\" for <shader> (did you mean \"Lambertian\"?); expected one of " + SHADER_TYPES),
                row("type of the wrong kind is unknown for that element", """
                        <scene>
                          <camera type="Sphere"/>
                          <image>4 3</image>
                        </scene>
                        """, 2, 26, "unknown type \"Sphere\" for <camera>; expected one of PerspectiveCamera, OrthographicCamera"),
                // Transformed is a Surface, but only a Group makes one (around itself).
                row("type without a constructor without arguments cannot be made", body("""
                          <surface type="Transformed"/>
                        """), 4, 32, "type \"Transformed\" cannot be made from a scene file (it has no"
                                + " public constructor without arguments); expected one of " + SURFACE_TYPES),
                row("surface without type lists the types", body("""
                          <surface>
                            <radius>1</radius>
                          </surface>
                        """), 4, 12, "<surface> needs a type attribute; expected one of " + SURFACE_TYPES),
                row("shader name written as text points to ref", body(SHADER_BLUE + """
                          <surface type="Sphere">
                            <shader>blue</shader>
                          </surface>
                        """), 6, 13, "<shader> needs a type attribute; expected one of " + SHADER_TYPES
                                + " (to reuse a named object, write <shader ref=\"blue\"/>)"),
                // "  <surface type=\"Sphere\" color=\"red\">" is 37 characters.
                row("unknown attribute on an object element", body("""
                          <surface type="Sphere" color="red">
                          </surface>
                        """), 4, 38, "unknown attribute color on <surface>; expected type, name or ref"),
                row("unknown attribute on a value element", """
                        <scene>
                          <camera type="PerspectiveCamera"/>
                          <image units="px">4 3</image>
                        </scene>
                        """, 3, 21, "unknown attribute units on <image>; expected no attributes"),
                row("unknown attribute on the scene", """
                        <scene version="2">
                          <camera type="PerspectiveCamera"/>
                          <image>4 3</image>
                        </scene>
                        """, 1, 20, "unknown attribute version on <scene>; expected no attributes"),
                row("ref to a name defined later says where it is", body("""
                          <surface type="Sphere">
                            <shader ref="late"/>
                          </surface>
                          <shader name="late" type="Lambertian"/>
                        """), 5, 25,
                        "ref \"late\" names an object defined later, on line 7; expected the name of an object defined before it"),
                row("ref to the object it is inside says so", body("""
                          <surface type="Group" name="outer">
                            <surface ref="outer"/>
                          </surface>
                        """), 5, 27,
                        "ref \"outer\" names the object it is inside (line 4); expected the name of an object defined before it"),
                row("ref to an object of the wrong kind", body(SHADER_BLUE + """
                          <surface ref="blue"/>
                        """), 5, 24, "ref \"blue\" names a Lambertian; expected a Surface"),
                row("ref with its own properties is refused", body(SHADER_BLUE + """
                          <surface type="Sphere">
                            <shader ref="blue">
                              <diffuseColor>1 0 0</diffuseColor>
                            </shader>
                          </surface>
                        """), 6, 24,
                        "<shader ref=\"blue\"> also has properties; expected the ref alone (it reuses the named object as it is)"),
                row("ref with a type and a name is refused", body(SHADER_BLUE + """
                          <shader ref="blue" type="Phong" name="shiny"/>
                        """), 5, 49,
                        "<shader ref=\"blue\"> also has a type and a name; expected the ref alone (it reuses the named object as it is)"),
                row("duplicate name is reported at its second definition", body(SHADER_BLUE + """
                          <shader name="blue" type="Phong"/>
                        """), 5, 37, "duplicate name \"blue\" (first given on line 4); expected each name to be used once"),

                // ---- References: what a ref that names nothing suggests, for each kind of object.
                // "    <shader ref=\"blu\"/>" ends in column 23: SAX places the element just after it.
                row("misspelled ref suggests a defined name", body(SHADER_BLUE + sphereWithShaderRef("blu")), 6, 24,
                        "unknown ref \"blu\" (did you mean \"blue\"?); expected the name of a Shader defined earlier in the file"),
                row("wrongly cased ref suggests the defined name", body(SHADER_BLUE + sphereWithShaderRef("Blue")), 6, 25,
                        "unknown ref \"Blue\" (did you mean \"blue\"?); expected the name of a Shader defined earlier in the file"),
                row("swapped letters suggest the defined name", body(SHADER_BLUE + sphereWithShaderRef("bleu")), 6, 25,
                        "unknown ref \"bleu\" (did you mean \"blue\"?); expected the name of a Shader defined earlier in the file"),
                row("a close name of another kind is not suggested", body("""
                          <shader name="red" type="Lambertian"/>
                          <surface type="Sphere" name="blue">
                            <shader ref="red"/>
                          </surface>
                        """ + sphereWithShaderRef("bleu")), 9, 25,
                        "unknown ref \"bleu\"; expected \"red\", the only Shader defined earlier in the file"),
                row("a far name lists the names of its kind", body("""
                          <shader name="red" type="Lambertian"/>
                          <shader name="green" type="Lambertian"/>
                          <shader name="blue" type="Phong"/>
                        """ + sphereWithShaderRef("purple")), 8, 27,
                        "unknown ref \"purple\"; expected one of the Shaders defined earlier in the file: \"blue\", \"green\", \"red\""),
                row("many names are listed up to ten", body(lambertianShaders(12) + sphereWithShaderRef("purple")), 17, 27,
                        "unknown ref \"purple\"; expected one of the Shaders defined earlier in the file: \"s01\", \"s02\", \"s03\","
                                + " \"s04\", \"s05\", \"s06\", \"s07\", \"s08\", \"s09\", \"s10\" and 2 more"),
                row("no name of the kind says none is defined", body("""
                          <shader name="matte" type="Lambertian">
                            <texture ref="wood"/>
                          </shader>
                        """), 5, 26,
                        "unknown ref \"wood\"; expected the name of a Texture defined earlier in the file (none is defined before this ref)"),
                row("surface ref in a group suggests a surface", body(SHADER_BLUE + """
                          <surface type="Sphere" name="ball">
                            <shader ref="blue"/>
                          </surface>
                          <surface type="Group">
                            <surface ref="bal"/>
                          </surface>
                        """), 9, 25,
                        "unknown ref \"bal\" (did you mean \"ball\"?); expected the name of a Surface defined earlier in the file"),
                row("substrate ref suggests a shader", body("""
                          <shader name="matte" type="Phong"/>
                          <shader name="glaze" type="Glazed">
                            <substrate ref="mate"/>
                          </shader>
                        """), 6, 28,
                        "unknown ref \"mate\" (did you mean \"matte\"?); expected the name of a Shader defined earlier in the file"),
                row("light ref suggests a light", body("""
                          <light name="key">
                            <position>0 5 0</position>
                            <intensity>1 1 1</intensity>
                          </light>
                          <light ref="kye"/>
                        """), 8, 21,
                        "unknown ref \"kye\" (did you mean \"key\"?); expected the name of a Light defined earlier in the file"),

                // ---- Values: counts, words where numbers belong, fractions where integers belong, values out
                // of range, a mesh without its file, a scene without a camera or an image size.
                row("vector with two values asks for three", sphere("    <center>1 2</center>\n"), 5, 13,
                        "<center> has 2 values; expected " + THREE_CENTER_NUMBERS),
                row("vector with four values asks for three", sphere("    <center>1 2 3 4</center>\n"), 5, 13,
                        "<center> has 4 values; expected " + THREE_CENTER_NUMBERS),
                row("empty number asks for one", sphere("    <radius> </radius>\n"), 5, 13, "<radius> has no value; expected a number"),
                row("image with one value asks for two integers", """
                        <scene>
                          <camera type="PerspectiveCamera"/>
                          <image>300</image>
                        </scene>
                        """, 3, 10, "<image> has 1 value; expected two integers"),
                // Java's own parser would take NaN, Infinity, hex floats and a "d" suffix; a scene takes plain decimals.
                row("word abc in a radius is not a number", sphere("    <radius>abc</radius>\n"), 5, 13,
                        "\"abc\" in <radius> is not a number; expected a number"),
                row("NaN in a radius is not a number", sphere("    <radius>NaN</radius>\n"), 5, 13,
                        "\"NaN\" in <radius> is not a number; expected a number"),
                row("Infinity in a radius is not a number", sphere("    <radius>Infinity</radius>\n"), 5, 13,
                        "\"Infinity\" in <radius> is not a number; expected a number"),
                row("-Infinity in a radius is not a number", sphere("    <radius>-Infinity</radius>\n"), 5, 13,
                        "\"-Infinity\" in <radius> is not a number; expected a number"),
                row("hex float 0x10 in a radius is not a number", sphere("    <radius>0x10</radius>\n"), 5, 13,
                        "\"0x10\" in <radius> is not a number; expected a number"),
                row("1d with a d suffix in a radius is not a number", sphere("    <radius>1d</radius>\n"), 5, 13,
                        "\"1d\" in <radius> is not a number; expected a number"),
                row("decimal comma 1,5 in a radius is not a number", sphere("    <radius>1,5</radius>\n"), 5, 13,
                        "\"1,5\" in <radius> is not a number; expected a number"),
                row("NaN in a vector is not a number", sphere("    <center>0 NaN 0</center>\n"), 5, 13,
                        "\"NaN\" in <center> is not a number; expected " + THREE_CENTER_NUMBERS),
                row("Infinity in a vector is not a number", sphere("    <center>0 Infinity 0</center>\n"), 5, 13,
                        "\"Infinity\" in <center> is not a number; expected " + THREE_CENTER_NUMBERS),
                row("-Infinity in a vector is not a number", sphere("    <center>0 -Infinity 0</center>\n"), 5, 13,
                        "\"-Infinity\" in <center> is not a number; expected " + THREE_CENTER_NUMBERS),
                row("inf in a vector is not a number", sphere("    <center>0 inf 0</center>\n"), 5, 13,
                        "\"inf\" in <center> is not a number; expected " + THREE_CENTER_NUMBERS),
                row("number beyond double range is too large", sphere("    <center>0 1e999 0</center>\n"), 5, 13,
                        "\"1e999\" in <center> is too large; expected " + THREE_CENTER_NUMBERS),
                row("fractional image size is not an integer", """
                        <scene>
                          <camera type="PerspectiveCamera"/>
                          <image>300.5 200</image>
                        </scene>
                        """, 3, 10, "\"300.5\" in <image> is not an integer; expected two integers"),
                row("image size beyond int is too large", """
                        <scene>
                          <camera type="PerspectiveCamera"/>
                          <image>300 99999999999</image>
                        </scene>
                        """, 3, 10, "\"99999999999\" in <image> is too large; expected two integers"),
                row("fractional samples is not an integer", body("  <samples>2.5</samples>\n"), 4, 12,
                        "\"2.5\" in <samples> is not an integer; expected an integer"),
                row("negative radius is invalid", sphere("    <radius>-1</radius>\n"), 5, 13, "radius is -1.0; expected a positive number"),
                row("zero radius is invalid", sphere("    <radius>0</radius>\n"), 5, 13, "radius is 0.0; expected a positive number"),
                row("zero image size is invalid", """
                        <scene>
                          <camera type="PerspectiveCamera"/>
                          <image>0 3</image>
                        </scene>
                        """, 3, 10, "image size is 0 3; expected two positive integers"),
                row("negative image size is invalid", """
                        <scene>
                          <camera type="PerspectiveCamera"/>
                          <image>-4 3</image>
                        </scene>
                        """, 3, 10, "image size is -4 3; expected two positive integers"),
                row("zero samples is invalid", body("  <samples>0</samples>\n"), 4, 12, "samples is 0; expected a positive integer"),
                row("negative samples is invalid", body("  <samples>-2</samples>\n"), 4, 12, "samples is -2; expected a positive integer"),
                row("negative exposure is invalid", body("  <exposure>-0.5</exposure>\n"), 4, 13, "exposure is -0.5; expected a number ≥ 0"),
                row("zero viewWidth is invalid", camera("PerspectiveCamera", "<viewWidth>0</viewWidth>"), 3, 16, "viewWidth is 0.0; expected a positive number"),
                row("zero viewHeight is invalid", camera("OrthographicCamera", "<viewHeight>0</viewHeight>"), 3, 17, "viewHeight is 0.0; expected a positive number"),
                row("zero projDistance is invalid", camera("PerspectiveCamera", "<projDistance>0</projDistance>"), 3, 19, "projDistance is 0.0; expected a positive number"),
                row("negative projDistance is invalid", camera("PerspectiveCamera", "<projDistance>-1.5</projDistance>"), 3, 19, "projDistance is -1.5; expected a positive number"),
                // The axes are checked once the whole camera is read, so the error points at <camera>.
                row("zero viewDir is reported at its camera", camera("PerspectiveCamera", "<viewDir>0 0 0</viewDir>"), 2, 36, "invalid PerspectiveCamera: viewDir is (0.0, 0.0, 0.0); expected a nonzero vector"),
                row("viewUp parallel to viewDir is reported at its camera", """
                        <scene>
                          <camera type="OrthographicCamera">
                            <viewDir>0 0 -1</viewDir>
                            <viewUp>0 0 2</viewUp>
                          </camera>
                          <image>4 3</image>
                        </scene>
                        """, 2, 37, "invalid OrthographicCamera: viewUp (0.0, 0.0, 2.0) is parallel to"
                                + " viewDir (0.0, 0.0, -1.0); expected a viewUp that is not parallel to viewDir"),
                row("zero viewUp is reported at its camera", camera("PerspectiveCamera", "<viewUp>0 0 0</viewUp>"), 2, 36,
                        "invalid PerspectiveCamera: viewUp is (0.0, 0.0, 0.0); expected a nonzero vector not parallel to viewDir"),
                row("zero scale is refused", body("""
                          <surface type="Group">
                            <scale>1 0 1</scale>
                            <surface type="Sphere"/>
                          </surface>
                        """), 4, 25,
                        "invalid Group: scale (1.0, 0.0, 1.0) is zero on an axis; expected a nonzero scale on every axis"),
                row("empty mesh path asks for a file", body("""
                          <surface type="Mesh">
                            <data> </data>
                          </surface>
                        """), 5, 11, "<data> is empty; expected a file path"),
                row("mesh without data asks for it", body("""
                          <surface type="Mesh">
                          </surface>
                        """), 4, 24, "invalid Mesh: no <data> is given; expected <data> with the path of an OBJ file"),
                row("scene without camera is reported at the scene element", """
                        <?xml version="1.0"?>
                        <scene>
                          <image>4 3</image>
                        </scene>
                        """, 2, 8, "the scene has no <camera>; expected a camera, e.g. <camera type=\"PerspectiveCamera\"/>"),
                row("scene without image is reported at the scene element", """
                        <scene>
                          <camera type="PerspectiveCamera"/>
                        </scene>
                        """, 1, 8, "the scene has no <image> size; expected <image>width height</image>"),

                // ---- XML: malformed markup, the wrong root, text where elements belong, a file that is empty
                // or holds no element.
                // The parser stops inside "</camra>" (columns 3 to 10 of line 3).
                row("mismatched end tag is malformed XML at that tag", """
                        <scene>
                          <camera type="PerspectiveCamera">
                          </camra>
                        </scene>
                        """, 3, 5, "malformed XML: </camra> does not close <camera>; expected </camera>"),
                // The quote opened on line 2 runs on into line 3, where the parser stops at the "<" of "<image>".
                row("unclosed attribute quote is malformed XML where the parser notices", """
                        <scene>
                          <camera type="PerspectiveCamera/>
                          <image>4 3</image>
                        </scene>
                        """, 3, 3, "malformed XML: the value of attribute type of"
                                + " <camera> runs into a '<'; expected its closing quote before that (write a '<' inside a value as &lt;)"),
                // Located at the <scene> left open; the parser noticed at the end of the file, after the last newline.
                row("truncated file is malformed XML", """
                        <scene>
                          <camera type="PerspectiveCamera"/>
                        """, 1, 1,
                        "malformed XML: <scene> is never closed (the file ends at 3:1); expected </scene> before the end of the file"),
                row("unclosed comment is reported where it starts", """
                        <scene>
                          <camera type="PerspectiveCamera"/>
                          <!-- the image size comes later
                          <image>4 3</image>
                        </scene>
                        """, 3, 3, "malformed XML: this comment is never closed; expected --> before the end of the file"),
                row("text before the root is malformed XML", """
                        scene:
                        <scene>
                        </scene>
                        """, 1, 1, "malformed XML: text before the first element; expected the file to start with <scene>"
                                + " (or an <?xml ...?> declaration)"),
                // The parser stops just past the '&' in column 12.
                row("bare ampersand asks for its entity", """
                        <scene>
                          <camera type="PerspectiveCamera"/>
                          <image>4 & 3</image>
                        </scene>
                        """, 3, 13, "malformed XML: a '&' that starts no entity; expected &amp; for an '&' in text"),
                // Located where the start tag ends, as every element is.
                row("attribute given twice is reported on its element", """
                        <scene>
                          <camera type="PerspectiveCamera" type="OrthographicCamera"/>
                          <image>4 3</image>
                        </scene>
                        """, 2, 61, "malformed XML: attribute type is given twice on <camera>; expected each attribute once"),
                row("control character in text is named by its code point", "<scene>\n  <image>4\u0001 3</image>\n</scene>\n", 2, 11,
                        "malformed XML: character U+0001 is not allowed in XML (in element text); expected printable text"),
                // A rare mistake keeps the words of the JDK's parser, which the loader asks for in English.
                row("other malformed XML keeps the English words of the parser", """
                        <?xml version="1.0" standalone="maybe"?>
                        <scene/>
                        """, 1, 39, "malformed XML: The standalone document declaration"
                                + " value must be \"yes\" or \"no\", not \"maybe\"; expected well-formed XML"),
                row("empty file is reported as empty", "", 1, 1, "the file is empty; expected a <scene> element"),
                row("file without elements is reported as such", "<?xml version=\"1.0\"?>\n<!-- nothing yet -->\n", 3, 1,
                        "the file has no elements; expected a <scene> element"),
                row("root other than scene is refused", """
                        <?xml version="1.0"?>
                        <scenery>
                        </scenery>
                        """, 2, 10, "the root element is <scenery>; expected <scene>"),
                row("text among elements is reported where the text starts", """
                        <scene>
                          <camera type="PerspectiveCamera"/>
                          radius 2
                          <image>4 3</image>
                        </scene>
                        """, 3, 3, "unexpected text \"radius 2\" in <scene>; expected only elements here"),
                row("text over several lines is quoted on one line and cut", """
                        <scene>
                          <camera type="PerspectiveCamera"/>
                          radius 2
                          center 0 0 -5
                          and a very long sentence after that
                          <image>4 3</image>
                        </scene>
                        """, 3, 3, "unexpected text \"radius 2 center 0 0 -5 and a very lon...\" in <scene>; expected only elements here"),
                // "    <radius>1</radius> " is 23 characters, so "oops" starts in column 24.
                row("text after a property is reported where the text starts", sphere("    <radius>1</radius> oops\n"), 5, 24,
                        "unexpected text \"oops\" in <surface>; expected only elements here"),
                row("text after a comment and tabs is located past them",
                        "<scene>\n  <!-- a comment\n  over two lines -->\n\t\tstray\n</scene>\n", 4, 3,
                        "unexpected text \"stray\" in <scene>; expected only elements here"),
                // "  <![CDATA[  " is 13 characters.
                row("text in a CDATA section is located inside it", "<scene>\n  <![CDATA[  stray ]]>\n</scene>\n", 2, 14,
                        "unexpected text \"stray\" in <scene>; expected only elements here"),
                row("property holding elements is refused", body("""
                          <surface type="Sphere">
                            <radius>
                              <value>1</value>
                            </radius>
                          </surface>
                        """), 5, 13, "<radius> holds elements; expected only a value"));
    }

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private final String scene;
    private final int line;
    private final int column;
    private final String problem;

    public SceneLoaderErrorsTest(String name, String scene, int line, int column, String problem) {
        this.scene = scene;
        this.line = line;
        this.column = column;
        this.problem = problem;
    }

    @Test
    public void loadingReportsTheErrorWhereItIs() {
        Path file = SceneFixtures.write(folder, "bad.xml", scene);
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, line, column, problem);
    }

    /** One case: its name, the scene text, and where the error must point and what it must say. */
    private static Object[] row(String name, String scene, int line, int column, String problem) {
        return new Object[] {name, scene, line, column, problem};
    }

    /** {@code <scene>}, a camera and an image size (lines 1 to 3), then {@code body} from line 4, then {@code </scene>}. */
    private static String body(String body) {
        return "<scene>\n" + SceneFixtures.CAMERA_AND_IMAGE + body + "</scene>\n";
    }

    /** A {@link #body} of a sphere that starts on line 4 and whose line 5 is {@code line}. */
    private static String sphere(String line) {
        return body("  <surface type=\"Sphere\">\n" + line + "  </surface>\n");
    }

    /** A 4×3 scene whose camera of type {@code type} has one property, {@code property}, on line 3. */
    private static String camera(String type, String property) {
        return "<scene>\n  <camera type=\"" + type + "\">\n    " + property + "\n  </camera>\n  <image>4 3</image>\n</scene>\n";
    }

    /** Three lines: a sphere whose shader is {@code <shader ref="ref"/>}, on the second of them. */
    private static String sphereWithShaderRef(String ref) {
        return "  <surface type=\"Sphere\">\n    <shader ref=\"" + ref + "\"/>\n  </surface>\n";
    }

    /** {@code count} lines, each a Lambertian shader named s01, s02, …. */
    private static String lambertianShaders(int count) {
        StringBuilder shaders = new StringBuilder();
        for (int i = 1; i <= count; i++) {
            shaders.append(String.format("  <shader name=\"s%02d\" type=\"Lambertian\"/>\n", i));
        }
        return shaders.toString();
    }
}
