package ray.scene;

import java.nio.file.Path;
import java.util.Deque;
import java.util.Iterator;
import org.w3c.dom.Element;

/**
 * Errors for something left open (an element, a comment, a CDATA section), located where it starts.
 * The parser notices only later, at an end tag that does not match or at the end of the file, and a
 * student looking there sees nothing wrong: the line to fix is the one that opened it. The place
 * where the parser noticed is still given, in the problem.
 */
final class Unclosed {
    private Unclosed() {
    }

    /**
     * The error for an element, comment or CDATA section left open, or null when the parser's
     * complaint is something else.
     *
     * @param open     the elements open where the parser stopped, innermost first
     * @param message  the parser's message
     * @param endTag   the end tag the parser stopped in, or null
     * @param line     where the parser stopped
     */
    static SceneException error(Path file, TextPositions text, Deque<Element> open, String message, FoundEndTag endTag,
            int line, int column) {
        if (open.isEmpty()) {
            return null;
        }
        if (XmlProblems.ENDS_INSIDE_MARKUP.equals(message)) {
            // Inside a comment or CDATA section an element's end tag is only text: the section is the problem.
            SceneException section = sectionAtEnd(file, text, "<!--", "-->", "comment");
            if (section == null) {
                section = sectionAtEnd(file, text, "<![CDATA[", "]]>", "CDATA section");
            }
            return section != null ? section
                    : element(file, text, open.peek(), "the file ends at " + line + ":" + column, "before the end of the file");
        }
        if (XmlProblems.UNMATCHED_END_TAG.matcher(String.valueOf(message)).matches() && endTag != null
                && closesAnOuterElement(open, endTag.name)) {
            return element(file, text, open.peek(), "found </" + SceneException.excerpt(endTag.name) + "> at " + endTag.line
                    + ":" + endTag.column, "before it");
        }
        // An end tag that closes nothing open is misspelled rather than early: XmlProblems says so where it is.
        return null;
    }

    /** Whether {@code name} is that of an element around the innermost open one, which is then left open. */
    private static boolean closesAnOuterElement(Deque<Element> open, String name) {
        Iterator<Element> outward = open.iterator();
        outward.next();
        while (outward.hasNext()) {
            if (outward.next().getTagName().equals(name)) {
                return true;
            }
        }
        return false;
    }

    /** The error at the start tag of {@code element}, which is never closed. */
    private static SceneException element(Path file, TextPositions text, Element element, String found, String before) {
        // SAX places an element just after its start tag's '>'; the tag starts at the '<' before that, as
        // no '<' can stand inside a tag (not even in an attribute's value).
        int[] end = PositionalXml.position(element);
        int tagStart = text.text().lastIndexOf('<', text.offset(end[0], end[1]) - 1);
        int[] start = tagStart >= 0 ? text.position(tagStart) : end;
        String name = SceneException.excerpt(element.getTagName());
        return new SceneException(file, start[0], start[1], "malformed XML: <" + name + "> is never closed (" + found
                + "); expected </" + name + "> " + before);
    }

    /**
     * The error for an {@code open}…{@code close} section (a comment or CDATA section) that the file
     * ends inside, located where it starts; null if the last one is closed.
     */
    private static SceneException sectionAtEnd(Path file, TextPositions text, String open, String close, String what) {
        int start = text.text().lastIndexOf(open);
        if (start < 0 || text.text().indexOf(close, start + open.length()) >= 0) {
            return null;
        }
        int[] where = text.position(start);
        return new SceneException(file, where[0], where[1],
                "malformed XML: this " + what + " is never closed; expected " + close + " before the end of the file");
    }
}
