package ray.fuzz;

/** The kinds of file a fuzz case damages: the scene itself, a mesh it names, or a texture image it names. */
enum FileKind {
    SCENE("scene"),
    MESH("mesh"),
    TEXTURE("texture");

    /** How the summary names the kind. */
    final String label;

    FileKind(String label) {
        this.label = label;
    }
}
