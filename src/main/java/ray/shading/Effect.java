package ray.shading;

/**
 * The effects a scene may call for, in the order a render plan lists them. Each shader and surface
 * reports the ones it needs ({@link Shader#effects()}, {@code Surface.effects()}), so the renderer
 * pays only for what a scene uses.
 */
public enum Effect {
    /** Shading by point lights (Lambertian, Phong), which runs when the scene also has a light. */
    LIGHTING("lighting"),
    /** One shadow ray per light with a nonzero contribution; needs what lighting needs. */
    SHADOWS("shadows"),
    /** The Blinn–Phong highlight. */
    SPECULAR("specular"),
    /** A texture lookup per shaded hit, replacing a shader's diffuse color. */
    TEXTURES("textures"),
    /** Mirror rays of a glaze, up to its depth cap. */
    REFLECTION("reflection"),
    /** More than one camera ray per pixel (asked for by the scene's samples, not by a surface). */
    ANTIALIASING("antialiasing"),
    /** Rays taken into a placed surface's own coordinates. */
    TRANSFORMS("transforms"),
    /** The barycentric blend of a triangle's vertex normals. */
    VERTEX_NORMALS("vertex normals"),
    /**
     * A bounding volume hierarchy searched inside a mesh or box of enough triangles, so that a ray
     * tests a few of them rather than all (the image is the same without it: {@code --accel none}).
     */
    ACCELERATION("bvh");

    public final String label;

    Effect(String label) {
        this.label = label;
    }
}
