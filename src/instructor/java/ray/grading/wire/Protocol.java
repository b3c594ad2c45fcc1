package ray.grading.wire;

/**
 * The messages between the judge (the grading process, which runs the tests and never a student
 * class) and the worker (the process that runs the student's classes and nothing secret). The judge
 * asks; the worker answers with plain data; the judge parses every answer strictly and decides
 * everything itself.
 *
 * <p>Judge to worker: {@link #CALL} (definitions, then one call), {@link #BATCH} (definitions, then
 * many calls whose answers may come together) and {@link #CALLBACK_ANSWER}. Worker to judge:
 * {@link #READY} once started, {@link #ANSWER}, {@link #BATCH_ANSWER}, {@link #CALLBACK} (the
 * student's code called a judge-side object during a call: a group's child, a shader's context, a
 * hit to shade) and {@link #EXITING} (the student's code called System.exit during a call).
 */
public final class Protocol {
    private Protocol() {
    }

    // Frame types, judge to worker.
    public static final int CALL = 1;
    public static final int BATCH = 2;
    public static final int CALLBACK_ANSWER = 3;
    // Frame types, worker to judge.
    public static final int READY = 10;
    public static final int ANSWER = 11;
    public static final int BATCH_ANSWER = 12;
    public static final int CALLBACK = 13;
    public static final int EXITING = 14;

    /** The first bytes of READY's payload: both sides must be built from the same grading code. */
    public static final String VERSION = "ray1-grading-wire-5";

    // Definitions, sent ahead of the calls that use them.
    /** A twin: the student's class made by its no-argument constructor (handle, class name). */
    public static final int DEF_TWIN = 1;
    /** The framework's fields of a twin (handle, class name, values in {@link FrameworkFields}' order). */
    public static final int DEF_STATE = 2;
    /** The judge called complete() on the stand-in: the twin's complete() runs too (handle). */
    public static final int DEF_COMPLETE = 3;
    /** A surface on the judge's side that a twin holds (a group's child): handle, its bounds, whether certified. */
    public static final int DEF_JUDGE = 4;
    /** A texture image: id, width, height, then its 3·w·h linear values. */
    public static final int DEF_IMAGE = 5;
    /**
     * A placement (the framework's Transformed) of something that holds a student's object, built again
     * on the worker's side so that the student's group searches it there: handle, the placed surface
     * (a reference), and the map to the world (9 numbers of its linear part, row-major, and 3 of its
     * translation).
     */
    public static final int DEF_PLACED = 6;
    /**
     * A set of twins of the student's triangles (a mesh's or a box's), built again on the worker's side
     * with the framework's tree over them, so that a ray asks the set once: handle, the count, each
     * twin's handle in order.
     */
    public static final int DEF_TRIANGLES = 7;
    /**
     * Nodes of a students' tree ({@code ray.bvh.BvhNode}) that a call names: a count, then each node
     * after its children: its handle, its box, whether a leaf, then its range or its children's handles.
     */
    public static final int DEF_NODES = 8;

    // How an object is named in a message.
    public static final int REF_NULL = 0;
    /** A stand-in on the judge's side, its twin on the worker's. */
    public static final int REF_TWIN = 1;
    /** A judge-side surface, a proxy on the worker's side. */
    public static final int REF_JUDGE = 2;
    /** An object the student's code made that the judge never sent (worker to judge only): its class name. */
    public static final int REF_FOREIGN = 3;
    /** A placement built on both sides ({@link #DEF_PLACED}). */
    public static final int REF_PLACED = 4;

    // Calls.
    public static final int OP_INTERSECT = 1;
    public static final int OP_GENERATE_RAY = 2;
    public static final int OP_TEX_COLOR = 3;
    /**
     * A shader's shade(hit, ray, context, depth): the twin, the hit (a record), the ray, the depth, the
     * scene's lights (count, then each position and intensity), and the color at the hit of the
     * shader's texture when it has one (a vector, or none): the texture stays on the judge's side, so
     * a texture the student's code gets wrong costs no shading points. The student's calls on the
     * context come back as callbacks ({@link #CB_UNOCCLUDED}, {@link #CB_RADIANCE}).
     */
    public static final int OP_SHADE = 4;
    /**
     * A ray tracer's shadeRay(ray, depth): the twin (whose surfaces are the scene's, a judge-side
     * surface), the ray and the depth. The student's code searches the scene through that surface
     * ({@link #CB_INTERSECT}) and has hits shaded by the judge ({@link #CB_SHADE_HIT}).
     */
    public static final int OP_SHADE_RAY = 5;
    /**
     * A BRDF's value(rhoD, n, l, v): the twin (whose parameters, such as the Phong BRDF's ks and p, are
     * its framework state) and the four vectors; the answer a vector. A pure function: no callbacks.
     */
    public static final int OP_BRDF_VALUE = 6;
    /** A microfacet distribution's D: n and h; the answer a number. */
    public static final int OP_MICROFACET_D = 7;
    /** A microfacet distribution's G1: x, n and h; the answer a number. */
    public static final int OP_MICROFACET_G1 = 8;
    /** A Fresnel factor's reflectance: the cosine; the answer a number. */
    public static final int OP_FRESNEL = 9;
    /** The box of a sphere (BoundingBoxes.ofSphere): center and radius; the answer a box or null. */
    public static final int OP_BOX_OF_SPHERE = 10;
    /** The box of a triangle (BoundingBoxes.ofTriangle): three corners; the answer a box or null. */
    public static final int OP_BOX_OF_TRIANGLE = 11;
    /** The slab test (BoundingBoxes.hit): a box or null, and the ray; the answer a boolean. */
    public static final int OP_BOX_HIT = 12;
    /**
     * A tree's build (BvhTree.build): the twin (whose boxes and order are its state), start and end; the
     * answer the order the build left and the tree it returned, as a table (children first).
     */
    public static final int OP_TREE_BUILD = 13;
    /**
     * A tree's closest-hit search (BvhTree.closestHit): the twin, a node (its handle, the nodes sent as
     * {@link #DEF_NODES}), the ray and the record; the answer as an intersect's, then the boxes the
     * search tested. Each primitive test comes back as {@link #CB_PRIMITIVE}, where the judge counts it.
     */
    public static final int OP_TREE_CLOSEST = 14;
    /** A tree's any-hit search (BvhTree.anyHit): the twin, a node and the ray; the answer a boolean and the boxes tested. */
    public static final int OP_TREE_ANY = 15;
    /** The box of a capped cylinder (BoundingBoxes.ofCylinder): center, radius and height; the answer a box or null. */
    public static final int OP_BOX_OF_CYLINDER = 16;

    // What a callback asks (its first byte), worker to judge, during a call.
    /** A judge-side surface's intersect: its handle, the ray, the record. */
    public static final int CB_INTERSECT = 1;
    /**
     * The shading context's shadow test: which hit the student's code passed ({@link #HIT_NULL},
     * {@link #HIT_GIVEN}: the one the call gave, then the judge tests its own, or {@link #HIT_OTHER}),
     * the hit as a record unless null, and the light's position; the answer is a boolean.
     */
    public static final int CB_UNOCCLUDED = 2;
    /** The shading context's mirror radiance: the hit as for {@link #CB_UNOCCLUDED}, the direction and the depth; the answer a vector. */
    public static final int CB_RADIANCE = 3;
    /** A shading callback's hit: null, the very record the shade call gave, or another record. */
    public static final int HIT_NULL = 0;
    public static final int HIT_GIVEN = 1;
    public static final int HIT_OTHER = 2;
    /** A ray tracer's shading of a hit: the hit (a record), the ray and the depth; the answer a vector. */
    public static final int CB_SHADE_HIT = 4;
    /**
     * A 2019 shader's BRDF value, asked during its shade call (the BRDF stays on the judge's side, so
     * a BRDF the student got wrong in another task costs no reflection points): ρd, n, l and v; the
     * answer a vector.
     */
    public static final int CB_BRDF = 5;
    /**
     * A test of a students' tree's primitive, which stays on the judge's side: the tree's twin, the
     * primitive's place in the scene's order, whether any hit will do (then only the ray; the answer a
     * boolean), else the ray and the record (the answer as {@link #CB_INTERSECT}'s).
     */
    public static final int CB_PRIMITIVE = 6;

    // Answers.
    public static final int RETURNED = 0;
    public static final int THREW = 1;
    /** Batches only: the call needs judge-side answers it was not given; asked again with them. */
    public static final int NEED = 2;

    /** The most lights a shade call carries. */
    public static final int MAX_LIGHTS = 10_000;

    // Limits on what the worker may send.
    /** Characters of an exception's message kept. */
    public static final int MAX_MESSAGE_BYTES = 16_000;
    /** Bytes of a class, method or file name. */
    public static final int MAX_NAME_BYTES = 512;

    /** {@code name} (of a class, method or file) cut to what a reader takes: UTF-8 takes at most four bytes a character. */
    public static String cutName(String name) {
        return name.length() <= MAX_NAME_BYTES / 4 ? name : name.substring(0, MAX_NAME_BYTES / 4);
    }
    /** Frames of a stack trace kept, and causes followed. */
    public static final int MAX_FRAMES = 64;
    public static final int MAX_CAUSES = 4;
    /** Entries of any table in one message. */
    public static final int MAX_ENTRIES = 4_000_000;
    /** Fields of a framework state, surfaces of a group. */
    public static final int MAX_PARTS = 1_000_000;
}
