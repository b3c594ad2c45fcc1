package ray.scene;

import java.util.List;
import ray.camera.Camera;
import ray.shading.Shader;
import ray.shading.Texture;
import ray.shading.legacy.MicrofacetBrdfElement;
import ray.surface.Surface;

/**
 * The built-in types of each kind, for error messages and suggestions only: the loader itself
 * finds any class by name, so a new surface needs no entry here to load.
 */
final class KnownTypes {
    private KnownTypes() {
    }

    static List<String> of(Class<?> base) {
        if (base == Surface.class) {
            return List.of("Sphere", "Triangle", "Box", "Mesh", "Cylinder", "Group");
        }
        if (base == Shader.class) {
            return List.of("Lambertian", "Phong", "MicrofacetBeckmann", "MicrofacetGGX", "Microfacet", "RGBNormals", "Glazed");
        }
        if (base == Texture.class) {
            return List.of("RepeatTexture", "ClampTexture");
        }
        if (base == Camera.class) {
            return List.of("PerspectiveCamera", "OrthographicCamera");
        }
        if (base == MicrofacetBrdfElement.class) {
            return List.of("Beckmann", "GGX");
        }
        return List.of(base.getSimpleName());
    }
}
