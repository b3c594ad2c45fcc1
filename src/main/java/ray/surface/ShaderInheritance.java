package ray.surface;

import ray.shading.Shader;

/**
 * The scene format's rule for surfaces without a shader: each takes the shader of the nearest
 * surface above it that has one (a group's, a box's or a mesh's), and the top of the scene takes a
 * default. Applied once to the whole tree when a scene is completed, so surfaces themselves hold
 * no inheritance code.
 */
public final class ShaderInheritance {
    private ShaderInheritance() {
    }

    /** Gives every surface under {@code root} (and root) without a shader the nearest one above it, or {@code fallback}. */
    public static void apply(Surface root, Shader fallback) {
        if (root.getShader() == null) {
            root.setShader(fallback);
        }
        for (Surface child : root.children()) {
            apply(child, root.getShader());
        }
    }
}
