package ray.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Scene variants for the effect benchmarks, written as scene files so that the renderer runs them
 * exactly as it runs any scene (the plan decides from the file; nothing is switched in code). All
 * share one geometry, modelled on the performance anchor of REFERENCES.md (a 160×120 scene of 26
 * primitives and two point lights): 24 spheres on a ground of two triangles. Each variant adds one
 * effect to {@code lit} or takes one away:
 * <ul>
 * <li>{@code lit}: Lambertian, two lights (lighting and shadows);</li>
 * <li>{@code unlit}: no lights, so no lighting and no shadow rays;</li>
 * <li>{@code normals}: RGBNormals, no lights: a scene that calls for no effect at all;</li>
 * <li>{@code phong}: {@code lit} with Phong shaders (specular);</li>
 * <li>{@code glazed}: {@code lit} with the spheres glazed (reflection rays);</li>
 * <li>{@code antialiased}: {@code lit} at 4 samples per pixel (a 2×2 grid);</li>
 * <li>{@code transformed}: {@code lit} with everything in a group placed by a rotation (transforms).</li>
 * </ul>
 */
final class EffectScenes {
    static final String[] VARIANTS = {"lit", "unlit", "normals", "phong", "glazed", "antialiased", "transformed"};

    private EffectScenes() {
    }

    /** Writes {@code NAME.xml} for every variant into {@code folder}. */
    static void writeAll(Path folder) {
        try {
            Files.createDirectories(folder);
            for (String variant : VARIANTS) {
                Files.write(folder.resolve(variant + ".xml"), xml(variant).getBytes(StandardCharsets.UTF_8));
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static String xml(String variant) {
        boolean lights = !variant.equals("unlit") && !variant.equals("normals");
        boolean grouped = variant.equals("transformed");
        StringBuilder s = new StringBuilder();
        s.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<scene>\n");
        s.append("  <camera type=\"PerspectiveCamera\">\n    <viewPoint>0 4 7</viewPoint>\n"
                + "    <viewDir>0 -4 -7</viewDir>\n    <projDistance>1.2</projDistance>\n"
                + "    <viewWidth>1.2</viewWidth>\n    <viewHeight>0.9</viewHeight>\n  </camera>\n");
        s.append("  <image>160 120</image>\n");
        if (variant.equals("antialiased")) {
            s.append("  <samples>4</samples>\n");
        }
        if (lights) {
            s.append("  <light><position>-4 6 5</position><intensity>40 40 40</intensity></light>\n");
            s.append("  <light><position>5 4 -2</position><intensity>15 15 18</intensity></light>\n");
        }
        s.append("  <shader name=\"ground\" ").append(shader(variant, "0.6 0.6 0.55", false)).append("\n");
        s.append("  <shader name=\"ball\" ").append(shader(variant, "0.7 0.3 0.2", true)).append("\n");
        String indent = "  ";
        if (grouped) {
            // Rotating everything about the vertical axis through the origin keeps the picture's content.
            s.append("  <surface type=\"Group\">\n    <rotate>0 15 0</rotate>\n");
            indent = "    ";
        }
        s.append(indent).append("<surface type=\"Triangle\"><shader ref=\"ground\"/>"
                + "<v0>-6 0 -6</v0><v1>-6 0 6</v1><v2>6 0 6</v2></surface>\n");
        s.append(indent).append("<surface type=\"Triangle\"><shader ref=\"ground\"/>"
                + "<v0>-6 0 -6</v0><v1>6 0 6</v1><v2>6 0 -6</v2></surface>\n");
        for (int row = 0; row < 4; row++) {
            for (int column = 0; column < 6; column++) {
                s.append(indent).append(String.format(Locale.ROOT,
                        "<surface type=\"Sphere\"><shader ref=\"ball\"/><center>%.2f 0.35 %.2f</center>"
                                + "<radius>0.35</radius></surface>\n", -2.5 + column, -1.5 + row));
            }
        }
        if (grouped) {
            s.append("  </surface>\n");
        }
        return s.append("</scene>\n").toString();
    }

    private static String shader(String variant, String color, boolean ball) {
        switch (variant) {
            case "normals":
                return "type=\"RGBNormals\"/>";
            case "phong":
                return "type=\"Phong\"><diffuseColor>" + color + "</diffuseColor>"
                        + "<specularColor>0.5 0.5 0.5</specularColor><exponent>50</exponent></shader>";
            case "glazed":
                if (ball) {
                    return "type=\"Glazed\"><refractiveIndex>1.5</refractiveIndex><substrate type=\"Lambertian\">"
                            + "<diffuseColor>" + color + "</diffuseColor></substrate></shader>";
                }
                // fall through: the ground stays Lambertian
            default:
                return "type=\"Lambertian\"><diffuseColor>" + color + "</diffuseColor></shader>";
        }
    }
}
