package ray.scene;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.regex.Pattern;
import org.w3c.dom.Element;
import org.w3c.dom.NamedNodeMap;
import org.w3c.dom.Node;
import ray.camera.Camera;
import ray.shading.BrdfShader;
import ray.shading.MicrofacetBrdfParameters;
import ray.shading.MicrofacetFactorBrdf;
import ray.shading.OnlyInCourse;
import ray.shading.Shader;
import ray.shading.Texture;
import ray.math.Vec3;
import ray.surface.MeshData;
import ray.surface.Placement;
import ray.surface.Surface;
import ray.surface.WarnsOnLoad;

/**
 * Loads the course's XML scene format by binding elements to setters: {@code <radius>} calls
 * {@code setRadius}, {@code <light>} calls {@code addLight}, {@code type="Sphere"} makes a
 * {@code ray.surface.Sphere} (the package of the setter's parameter type). A new surface or
 * shader is a new class; the loader does not change.
 *
 * <p>A setter's parameter types say how to read the element: numbers ({@code int}, {@code double},
 * one per parameter: {@code <image>300 200</image>} calls {@code setImage(int, int)}), {@link Vec3}
 * (three numbers), {@code String}, {@link Path} (a data path: see {@link #resolve}),
 * {@link MeshData} (an OBJ file read by {@link ObjReader}), or an object built from the element's
 * children. Element names match case-insensitively. After an object's properties are set, its
 * {@code complete()} method, if any, checks it and may return the object to use instead.
 *
 * <p>Every error is a {@link SceneException} naming the file, line and column. An object that
 * loads but deserves a remark ({@link WarnsOnLoad}, e.g. a box given with minPt above maxPt) adds
 * a warning to the scene, located in the same way: {@code FILE:LINE:COL: warning: what}
 * ({@link Scene#warnings()}).
 */
public final class SceneLoader {
    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");
    private static final Pattern INTEGER = Pattern.compile("[+-]?\\d+");

    private final Path file;
    private final SceneOptions options;
    /** Elements of another course's conventions ({@link OnlyInCourse}), refused together once the file is read. */
    private final List<Element> otherCourse = new ArrayList<>();
    /** The course those elements belong to. */
    private String otherYear;
    private final Map<String, Object> named = new HashMap<>();
    /** The element that defined each name, for the line of the first one when a name is used twice. */
    private final Map<String, Element> namedAt = new HashMap<>();
    /** Warnings of the completed objects, located, in the order they were completed. */
    private final List<String> warnings = new ArrayList<>();
    /** How many microfacet shaders show one factor alone ({@link SceneOptions#microfacetFactor}). */
    private int microfacetShaders;

    private SceneLoader(Path file, SceneOptions options) {
        this.file = file;
        this.options = options;
    }

    /**
     * Loads and checks a scene by the running assignment's course conventions, its data paths
     * starting from its folder; its name is the file name without ".xml".
     */
    public static Scene load(Path file) {
        return load(file, SceneOptions.ofAssignment());
    }

    /** Loads and checks a scene as {@code options} say (a course not given is the scene's folder's, {@link SceneOptions#forFile}). */
    public static Scene load(Path file, SceneOptions options) {
        return new SceneLoader(file, options.forFile(file)).loadScene();
    }

    private Scene loadScene() {
        Element root = PositionalXml.read(file).getDocumentElement();
        if (!root.getTagName().equalsIgnoreCase("scene")) {
            throw error(root, "the root element is <" + root.getTagName() + ">; expected <scene>");
        }
        checkAttributes(root, false);
        Scene scene = new Scene();
        scene.setName(SceneFiles.nameOf(file));
        scene.loadedFrom(file, options);
        setProperties(scene, null, root);
        if (!otherCourse.isEmpty()) {
            throw error(otherCourse.get(0), otherCourseProblem());
        }
        try {
            scene.complete(options.course);
        } catch (IllegalArgumentException e) {
            throw error(root, e.getMessage());
        }
        if (options.microfacetFactor != null && microfacetShaders == 0) {
            throw error(root, "a view of the microfacet factor " + options.microfacetFactor.name()
                    + " was asked for, and this scene has no microfacet shader (MicrofacetBeckmann, MicrofacetGGX or Microfacet)");
        }
        warnings.forEach(scene::warn);
        return scene;
    }

    /**
     * Applies each child element of {@code element} to {@code target} through its matching setter or
     * adder; a property that {@code target} has no setter for goes to {@code placement} (a surface's
     * translate, rotate and scale), when there is one.
     */
    private void setProperties(Object target, Placement placement, Element element) {
        for (Node node = element.getFirstChild(); node != null; node = node.getNextSibling()) {
            if (node.getNodeType() == Node.TEXT_NODE && !node.getTextContent().isBlank()) {
                throw error(node, "unexpected text \"" + excerpt(node.getTextContent().strip())
                        + "\" in <" + element.getTagName() + ">; expected only elements here");
            }
            if (node.getNodeType() != Node.ELEMENT_NODE) {
                continue;
            }
            Element property = (Element) node;
            Method setter = findSetter(target.getClass(), placement != null, property);
            OnlyInCourse only = setter.getAnnotation(OnlyInCourse.class);
            if (only != null && !only.value().equals(options.course.year)) {
                otherCourse.add(property);
                otherYear = only.value();
                continue;
            }
            Object receiver = setter.getDeclaringClass() == Placement.class ? placement : target;
            Object[] args = readArguments(property, setter);
            try {
                setter.invoke(receiver, args);
            } catch (InvocationTargetException e) {
                Throwable cause = e.getCause();
                if (cause instanceof SceneException) {
                    throw (SceneException) cause;
                }
                rethrowIfNotAboutTheScene(cause);
                throw error(property, refusal(property, propertyName(setter), cause));
            } catch (IllegalAccessException e) {
                throw error(property, "cannot set <" + property.getTagName() + "> (" + e.getMessage() + ")");
            }
        }
    }

    private Method findSetter(Class<?> type, boolean placed, Element property) {
        String name = property.getTagName();
        List<Method> candidates = new ArrayList<>(List.of(type.getMethods()));
        if (placed) {
            candidates.addAll(List.of(Placement.class.getMethods()));
        }
        for (Method m : candidates) {
            if (isProperty(m) && propertyName(m).equalsIgnoreCase(name)) {
                return m;
            }
        }
        TreeSet<String> known = new TreeSet<>();
        for (Method m : candidates) {
            if (isProperty(m)) {
                known.add(propertyName(m));
            }
        }
        String suggestion = Suggestions.closest(name, known);
        throw error(property, "unknown element <" + name + "> in " + describe(type)
                + (suggestion != null ? " (did you mean <" + suggestion + ">?)" : "")
                + (known.isEmpty() ? "; expected no elements inside it (it has no properties)"
                        : "; expected one of " + String.join(", ", known)));
    }

    /**
     * One line naming every element of another course's conventions and where each is: "<mirrorCoefficient>
     * (lines 12 and 20) is in the course's 2019 conventions only, and this scene loads by 2017's; …".
     */
    private String otherCourseProblem() {
        Map<String, List<Integer>> lines = new java.util.LinkedHashMap<>();
        for (Element e : otherCourse) {
            lines.computeIfAbsent(e.getTagName(), k -> new ArrayList<>()).add(PositionalXml.position(e)[0]);
        }
        List<String> parts = new ArrayList<>();
        for (Map.Entry<String, List<Integer>> entry : lines.entrySet()) {
            List<Integer> at = entry.getValue();
            parts.add("<" + entry.getKey() + "> (line" + (at.size() == 1 ? " " + at.get(0) : "s " + joinAnd(at)) + ")");
        }
        return joinAnd(parts) + (parts.size() == 1 ? " is" : " are") + " in the course's " + otherYear
                + " conventions only, and this scene loads by " + options.course.year + "'s; render it with --course "
                + otherYear + " (or set course = " + otherYear + " in assignment.properties)";
    }

    /** "a", "a and b", "a, b and c". */
    private static String joinAnd(List<?> items) {
        List<String> s = new ArrayList<>();
        items.forEach(i -> s.add(String.valueOf(i)));
        if (s.size() <= 1) {
            return String.join("", s);
        }
        return String.join(", ", s.subList(0, s.size() - 1)) + " and " + s.get(s.size() - 1);
    }

    /**
     * The problem of a setter that refused its value. Its message is the problem when it names the
     * property ("radius is -1.0; expected a positive number"); otherwise it follows "invalid <tag>: ".
     */
    private static String refusal(Element property, String propertyName, Throwable cause) {
        String message = cause.getMessage();
        if (message == null) {
            return "invalid <" + property.getTagName() + "> (" + cause.getClass().getSimpleName() + ")";
        }
        boolean namesProperty = message.regionMatches(true, 0, propertyName, 0, propertyName.length());
        return namesProperty ? message : "invalid <" + property.getTagName() + ">: " + message;
    }

    private static boolean isProperty(Method m) {
        String n = m.getName();
        return (n.startsWith("set") || n.startsWith("add")) && n.length() > 3 && m.getParameterCount() > 0
                && !Modifier.isStatic(m.getModifiers()) && !n.equals("setName");
    }

    private static String propertyName(Method m) {
        String rest = m.getName().substring(3);
        return Character.toLowerCase(rest.charAt(0)) + rest.substring(1);
    }

    private static String describe(Class<?> type) {
        return type == Scene.class ? "<scene>" : article(type.getSimpleName()) + type.getSimpleName();
    }

    /** "an OrthographicCamera", "a Sphere". */
    static String article(String word) {
        return "AEIOUaeiou".indexOf(word.charAt(0)) >= 0 ? "an " : "a ";
    }

    private Object[] readArguments(Element property, Method setter) {
        Class<?>[] types = setter.getParameterTypes();
        if (types.length == 1 && isObjectType(types[0])) {
            checkAttributes(property, true);
            return new Object[] {buildObject(property, types[0])};
        }
        checkAttributes(property, false);
        String text = textOf(property);
        if (types.length == 1 && types[0] == Vec3.class) {
            double[] v = numbers(property, text, 3, "three numbers, e.g. <" + property.getTagName() + ">1 0 -2.5</"
                    + property.getTagName() + ">");
            return new Object[] {new Vec3(v[0], v[1], v[2])};
        }
        if (types.length == 1 && types[0] == String.class) {
            return new Object[] {text.strip()};
        }
        if (types.length == 1 && types[0] == Path.class) {
            return new Object[] {resolve(property, text)};
        }
        if (types.length == 1 && types[0] == MeshData.class) {
            Path mesh = resolve(property, text);
            // Checked here so that the error points at the scene line that names the file; errors in
            // the file itself (empty, unreadable, bad lines) point into the file.
            if (!Files.exists(mesh)) {
                throw error(property, "no such mesh file " + mesh + "; expected an OBJ file (a relative path in <"
                        + property.getTagName() + "> starts from " + startsFrom() + ")");
            }
            if (Files.isDirectory(mesh)) {
                throw error(property, "the mesh path " + mesh + " is a folder; expected an OBJ file");
            }
            if (!Files.isRegularFile(mesh)) {
                throw error(property, "the mesh path " + mesh + " is not a regular file; expected an OBJ file");
            }
            return new Object[] {ObjReader.read(mesh)};
        }
        for (Class<?> t : types) {
            if (t != int.class && t != double.class) {
                throw new IllegalStateException(setter + " has a parameter type the loader cannot read: " + t);
            }
        }
        boolean allIntegers = types[0] == int.class;
        String expected = types.length == 1
                ? (allIntegers ? "an integer" : "a number")
                : numberWord(types.length) + (allIntegers ? " integers" : " numbers");
        String[] tokens = tokens(text);
        if (tokens.length != types.length) {
            throw error(property, "<" + property.getTagName() + "> has " + count(tokens.length) + "; expected " + expected);
        }
        Object[] args = new Object[types.length];
        for (int i = 0; i < types.length; i++) {
            if (types[i] == int.class) {
                if (!INTEGER.matcher(tokens[i]).matches()) {
                    throw error(property, "\"" + excerpt(tokens[i]) + "\" in <" + property.getTagName()
                            + "> is not an integer; expected " + expected);
                }
                try {
                    args[i] = Integer.parseInt(tokens[i]);
                } catch (NumberFormatException e) {
                    throw error(property, "\"" + excerpt(tokens[i]) + "\" in <" + property.getTagName()
                            + "> is too large; expected " + expected);
                }
            } else {
                args[i] = number(property, tokens[i], expected);
            }
        }
        return args;
    }

    private double[] numbers(Element property, String text, int n, String expected) {
        String[] tokens = tokens(text);
        if (tokens.length != n) {
            throw error(property, "<" + property.getTagName() + "> has " + count(tokens.length) + "; expected " + expected);
        }
        double[] values = new double[n];
        for (int i = 0; i < n; i++) {
            values[i] = number(property, tokens[i], expected);
        }
        return values;
    }

    private double number(Element property, String token, String expected) {
        // Java's parser also takes "NaN", "Infinity", hex floats and a 'd' suffix; a scene takes plain decimals.
        if (!NUMBER.matcher(token).matches()) {
            throw error(property, "\"" + excerpt(token) + "\" in <" + property.getTagName() + "> is not a number; expected "
                    + expected);
        }
        double value = Double.parseDouble(token);
        if (Double.isInfinite(value)) {
            throw error(property, "\"" + excerpt(token) + "\" in <" + property.getTagName() + "> is too large; expected "
                    + expected);
        }
        return value;
    }

    private static String[] tokens(String text) {
        String s = text.strip();
        return s.isEmpty() ? new String[0] : s.split("\\s+");
    }

    private static String count(int n) {
        return n == 0 ? "no value" : n == 1 ? "1 value" : n + " values";
    }

    /** "two", "three", "four", as in "expected two integers"; larger counts in digits. */
    private static String numberWord(int n) {
        return n >= 2 && n <= 4 ? new String[] {"two", "three", "four"}[n - 2] : Integer.toString(n);
    }

    /**
     * A data path (a mesh, a texture image): against the scene root when one is given; otherwise beside
     * the scene file, or, when it is not there, in the nearest folder above the scene's that has it, with
     * a warning naming where. That is how the course's 2019 scenes, kept in sub-folders of one root,
     * name their data ("../../meshes/bunny.obj" from the root), and they load as shipped.
     */
    private Path resolve(Element property, String text) {
        String path = text.strip();
        if (path.isEmpty()) {
            throw error(property, "<" + property.getTagName() + "> is empty; expected a file path");
        }
        if (options.sceneRoot != null) {
            return options.sceneRoot.resolve(path).normalize();
        }
        Path folder = file.toAbsolutePath().getParent();
        Path beside = folder.resolve(path).normalize();
        if (Files.exists(beside) || Path.of(path).isAbsolute()) {
            return beside;
        }
        for (Path above = folder.getParent(); above != null; above = above.getParent()) {
            Path found = above.resolve(path).normalize();
            if (Files.exists(found)) {
                int[] position = PositionalXml.position(property);
                warnings.add(SceneException.located(file, position[0], position[1], "warning: " + path
                        + " is not there from the scene's folder; using " + found + ", from " + above
                        + " (--scene-root DIR names the folder data paths start from)"));
                return found;
            }
        }
        return beside;
    }

    /** Where a relative data path starts, for messages about a file not found. */
    private String startsFrom() {
        return options.sceneRoot != null ? "the scene root " + options.sceneRoot + " (--scene-root)"
                : "the scene file's folder, or the nearest folder above it that has the file";
    }

    private static boolean isObjectType(Class<?> t) {
        return !t.isPrimitive() && t != String.class && t != Vec3.class && t != Path.class && t != MeshData.class;
    }

    /** Builds the object an element describes: a reference to a named one, or a new one of its type. */
    private Object buildObject(Element element, Class<?> baseType) {
        String ref = element.getAttribute("ref");
        if (!ref.isEmpty()) {
            List<String> extras = new ArrayList<>();
            for (String attribute : new String[] {"type", "name"}) {
                if (element.hasAttribute(attribute)) {
                    extras.add("a " + attribute);
                }
            }
            if (hasChildElements(element)) {
                extras.add("properties");
            }
            if (!extras.isEmpty()) {
                // "a type", "a type and properties", "a type, a name and properties".
                throw error(element, "<" + element.getTagName() + " ref=\"" + excerpt(ref) + "\"> also has " + joinAnd(extras)
                        + "; expected the ref alone (it reuses the named object as it is)");
            }
            Object found = named.get(ref);
            if (found == null) {
                throw error(element, UnknownRef.problem(element, ref, baseType, named));
            }
            if (!baseType.isInstance(found)) {
                throw error(element, "ref \"" + excerpt(ref) + "\" names " + article(found.getClass().getSimpleName())
                        + found.getClass().getSimpleName() + "; expected " + article(baseType.getSimpleName())
                        + baseType.getSimpleName());
            }
            return found;
        }
        Class<?> type = resolveType(element, baseType);
        Object object;
        try {
            object = type.getConstructor().newInstance();
        } catch (InvocationTargetException e) {
            rethrowIfNotAboutTheScene(e.getCause());
            // A bug in the class rather than in the scene: say what the constructor threw.
            throw error(element, "cannot create " + article(type.getSimpleName()) + type.getSimpleName()
                    + ": its constructor threw " + e.getCause());
        } catch (ReflectiveOperationException e) {
            throw error(element, "cannot create " + article(type.getSimpleName()) + type.getSimpleName() + " (" + e + ")");
        }
        Placement placement = object instanceof Surface ? new Placement() : null;
        setProperties(object, placement, element);
        object = complete(element, object, placement);
        String name = element.getAttribute("name");
        if (!name.isEmpty()) {
            Element first = namedAt.putIfAbsent(name, element);
            if (first != null) {
                throw error(element, "duplicate name \"" + excerpt(name) + "\" (first given on line "
                        + PositionalXml.position(first)[0] + "); expected each name to be used once");
            }
            named.put(name, object);
        }
        return object;
    }

    private Class<?> resolveType(Element element, Class<?> baseType) {
        String typeName = element.getAttribute("type");
        if (typeName.isEmpty()) {
            if (Modifier.isAbstract(baseType.getModifiers())) {
                // <shader>blue</shader> is a common way to try to reuse a named object.
                String text = hasChildElements(element) ? "" : element.getTextContent().strip();
                String hint = text.isEmpty() ? "" : " (to reuse a named object, write <" + element.getTagName()
                        + " ref=\"" + excerpt(text) + "\"/>)";
                throw error(element, "<" + element.getTagName() + "> needs a type attribute; expected one of "
                        + String.join(", ", KnownTypes.of(baseType)) + hint);
            }
            return baseType;
        }
        String qualified = typeName.contains(".") ? typeName : baseType.getPackageName() + "." + typeName;
        try {
            // Not initialized: a type name from a scene file must not run any class's static code
            // before it is known to be a surface, shader, camera or light.
            Class<?> type = Class.forName(qualified, false, SceneLoader.class.getClassLoader());
            if (baseType.isAssignableFrom(type) && !Modifier.isAbstract(type.getModifiers())) {
                if (!hasPublicConstructorWithoutArguments(type)) {
                    // Transformed, for one: made from a surface's placement, never written in a scene.
                    throw error(element, "type \"" + excerpt(typeName) + "\" cannot be made from a scene file (it has no"
                            + " public constructor without arguments); expected one of "
                            + String.join(", ", KnownTypes.of(baseType)));
                }
                return type;
            }
        } catch (ClassNotFoundException | NoClassDefFoundError e) {
            // Reported below. NoClassDefFoundError ("wrong name") is what a case-insensitive
            // file system gives for a wrongly cased name such as "sphere".
        }
        String suggestion = Suggestions.closest(typeName, KnownTypes.of(baseType));
        throw error(element, "unknown type \"" + excerpt(typeName) + "\" for <" + element.getTagName() + ">"
                + (suggestion != null ? " (did you mean \"" + suggestion + "\"?)" : "")
                + "; expected one of " + String.join(", ", KnownTypes.of(baseType)));
    }

    private static boolean hasPublicConstructorWithoutArguments(Class<?> type) {
        try {
            type.getConstructor();
            return true;
        } catch (NoSuchMethodException e) {
            return false;
        }
    }

    /**
     * Checks and finishes {@code object} ({@link #finish}), then records its warnings, if it has any,
     * at {@code element}, where an error in it would point.
     */
    private Object complete(Element element, Object object, Placement placement) {
        Object completed = finish(element, object, placement);
        if (object instanceof WarnsOnLoad) {
            int[] position = PositionalXml.position(element);
            for (String warning : ((WarnsOnLoad) object).warnings()) {
                warnings.add(SceneException.located(file, position[0], position[1], "warning: " + SceneException.oneLine(warning)));
            }
        }
        return completed;
    }

    /** Checks and finishes {@code object}; a surface comes back placed where its translate, rotate and scale put it. */
    /**
     * Running out of memory or stack, or a class that failed to initialize, says nothing about the
     * scene file: such errors go on as they are, to be named for what they are, never as "invalid <tag>".
     */
    private static void rethrowIfNotAboutTheScene(Throwable cause) {
        if (cause instanceof VirtualMachineError) {
            throw (VirtualMachineError) cause;
        }
        if (cause instanceof LinkageError) {
            throw (LinkageError) cause;
        }
    }

    private Object finish(Element element, Object object, Placement placement) {
        try {
            if (object instanceof Surface) {
                return placement.place(((Surface) object).complete());
            }
            if (object instanceof Camera) {
                ((Camera) object).complete();
            }
            if (object instanceof Texture) {
                ((Texture) object).complete();
            }
            if (object instanceof Shader) {
                ((Shader) object).complete();
                return withBrdfAsAsked(((Shader) object).forCourse(options.course));
            }
            return object;
        } catch (IllegalArgumentException e) {
            throw error(element, "invalid " + object.getClass().getSimpleName() + ": " + e.getMessage());
        }
    }

    /**
     * {@code shader}, whose BRDF the options replace when they ask to ({@link SceneOptions#brdfs}), and
     * whose microfacet BRDF shows the options' one factor alone when they ask for one.
     */
    private Shader withBrdfAsAsked(Shader shader) {
        if (options.brdfs != null && shader instanceof BrdfShader) {
            ((BrdfShader) shader).setBrdf(options.brdfs.apply(((BrdfShader) shader).brdf()));
        }
        if (options.microfacetFactor != null && shader instanceof BrdfShader && ((BrdfShader) shader).brdf() instanceof MicrofacetBrdfParameters) {
            BrdfShader brdfShader = (BrdfShader) shader;
            brdfShader.setBrdf(new MicrofacetFactorBrdf((MicrofacetBrdfParameters) brdfShader.brdf(), options.microfacetFactor));
            microfacetShaders++;
        }
        return shader;
    }

    private void checkAttributes(Element element, boolean objectElement) {
        NamedNodeMap attributes = element.getAttributes();
        for (int i = 0; i < attributes.getLength(); i++) {
            String attribute = attributes.item(i).getNodeName();
            boolean allowed = objectElement && (attribute.equals("type") || attribute.equals("name") || attribute.equals("ref"));
            if (!allowed) {
                throw error(element, "unknown attribute " + attribute + " on <" + element.getTagName() + ">; expected "
                        + (objectElement ? "type, name or ref" : "no attributes"));
            }
        }
    }

    private String textOf(Element property) {
        if (hasChildElements(property)) {
            throw error(property, "<" + property.getTagName() + "> holds elements; expected only a value");
        }
        return property.getTextContent();
    }

    private static boolean hasChildElements(Element element) {
        for (Node n = element.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n.getNodeType() == Node.ELEMENT_NODE) {
                return true;
            }
        }
        return false;
    }

    private static String excerpt(String s) {
        return SceneException.excerpt(s);
    }

    private SceneException error(Node node, String problem) {
        int[] position = PositionalXml.position(node);
        return new SceneException(file, position[0], position[1], problem);
    }
}
