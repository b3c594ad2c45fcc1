package ray.inspect;

import ray.IntersectionRecord;
import ray.math.Vec3;
import ray.shading.DirectLighting;
import ray.shading.Phong;
import ray.shading.Shader;
import ray.shading.Texture;

/**
 * The properties of the built-in shaders that the trace prints (kd or its texture, ks, the exponent); null for
 * a shader that has no such property, whose result the trace then prints alone.
 */
final class ShaderParameters {
    private ShaderParameters() {
    }

    static Vec3 diffuseColor(Shader shader) {
        return shader instanceof DirectLighting ? ((DirectLighting) shader).getDiffuseColor() : null;
    }

    /** The texture that replaces a lit shader's diffuse color, or null. */
    static Texture texture(Shader shader) {
        return shader instanceof DirectLighting ? ((DirectLighting) shader).getTexture() : null;
    }

    /** kd at a hit: a textured shader's texture color there, else its diffuse color. */
    static Vec3 diffuseColorAt(Shader shader, IntersectionRecord hit) {
        return shader instanceof DirectLighting ? ((DirectLighting) shader).diffuseColorAt(hit) : null;
    }

    static Vec3 specularColor(Shader shader) {
        return shader instanceof Phong ? ((Phong) shader).getSpecularColor() : null;
    }

    static Double exponent(Shader shader) {
        return shader instanceof Phong ? ((Phong) shader).getExponent() : null;
    }
}
