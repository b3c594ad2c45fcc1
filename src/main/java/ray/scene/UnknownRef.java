package ray.scene;

import java.util.Map;
import java.util.TreeSet;
import java.util.stream.Collectors;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;

/**
 * Why a ref names no object: it names the object it is inside, one defined later in the file, or
 * nothing. For nothing, the names it could have meant are only those of the kind the ref needs (a
 * shader's ref is never answered with a texture's name): the closest one as "did you mean", or else
 * all of them, so that a student sees what there is to choose from.
 */
final class UnknownRef {
    /** The most names a message lists; a scene with more gets "and N more", so the message stays one readable line. */
    private static final int MAX_LISTED = 10;

    private UnknownRef() {
    }

    /**
     * The problem of {@code ref} on {@code element}, which needs an object of type {@code kind};
     * {@code named} holds the objects defined (and completed) so far.
     */
    static String problem(Element element, String ref, Class<?> kind, Map<String, Object> named) {
        for (Node n = element.getParentNode(); n instanceof Element; n = n.getParentNode()) {
            if (((Element) n).getAttribute("name").equals(ref)) {
                return "ref " + quote(ref) + " names the object it is inside (line " + PositionalXml.position(n)[0]
                        + "); expected the name of an object defined before it";
            }
        }
        // Every object defined before the ref and not around it is complete and in named, so the rest come later.
        NodeList all = element.getOwnerDocument().getElementsByTagName("*");
        for (int i = 0; i < all.getLength(); i++) {
            Element e = (Element) all.item(i);
            if (e.getAttribute("name").equals(ref)) {
                return "ref " + quote(ref) + " names an object defined later, on line " + PositionalXml.position(e)[0]
                        + "; expected the name of an object defined before it";
            }
        }
        TreeSet<String> names = new TreeSet<>();
        named.forEach((name, object) -> {
            if (kind.isInstance(object)) {
                names.add(name);
            }
        });
        return "unknown ref " + quote(ref) + expected(ref, kind.getSimpleName(), names);
    }

    /** The "did you mean" and what was expected, from the defined names of the kind the ref needs. */
    private static String expected(String ref, String kind, TreeSet<String> names) {
        String earlier = " defined earlier in the file";
        String suggestion = Suggestions.closest(ref, names);
        if (suggestion != null) {
            return " (did you mean " + quote(suggestion) + "?); expected the name of " + SceneLoader.article(kind) + kind + earlier;
        }
        if (names.isEmpty()) {
            return "; expected the name of " + SceneLoader.article(kind) + kind + earlier + " (none is defined before this ref)";
        }
        if (names.size() == 1) {
            return "; expected " + quote(names.first()) + ", the only " + kind + earlier;
        }
        String listed = names.stream().limit(MAX_LISTED).map(UnknownRef::quote).collect(Collectors.joining(", "));
        String more = names.size() > MAX_LISTED ? " and " + (names.size() - MAX_LISTED) + " more" : "";
        return "; expected one of the " + kind + "s" + earlier + ": " + listed + more;
    }

    private static String quote(String name) {
        return "\"" + SceneException.excerpt(name) + "\"";
    }
}
