package ray.scene;

import java.util.List;
import java.util.Locale;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The XML parser's complaints in our own words: what is wrong and what was expected. The JDK's
 * parser (Xerces) says what rule was broken ("Attribute "type" was already specified for element
 * "shader"."); a student needs to hear what to write instead. The patterns match the parser's
 * base (English) messages, which {@link PositionalXml} asks for whatever the computer's language.
 * A message no pattern knows keeps the parser's words, followed by "; expected well-formed XML".
 */
final class XmlProblems {
    /** What the parser says when the file ends inside an element, comment or CDATA section. */
    static final String ENDS_INSIDE_MARKUP = "XML document structures must start and end within the same entity.";

    /** What the parser says at an end tag that does not close the innermost open element. */
    static final Pattern UNMATCHED_END_TAG =
            Pattern.compile("The element type \"([^\"]*)\" must be terminated by the matching end-tag .*");

    /**
     * A parser message and the problem it stands for, built from the message's quoted parts. (A
     * class, not a record: Gradle 4.4 cannot read a record's class file on the compile classpath.)
     */
    private static final class Translation {
        final Pattern message;
        final Function<Matcher, String> problem;

        Translation(String regex, Function<Matcher, String> problem) {
            this.message = Pattern.compile(regex);
            this.problem = problem;
        }
    }

    private static final String DECLARATION = "expected a declaration such as <?xml version=\"1.0\" encoding=\"UTF-8\"?>";

    private static final List<Translation> TRANSLATIONS = List.of(
            new Translation("The value of attribute \"([^\"]*)\" associated with an element type \"([^\"]*)\" must not contain the"
                    + " '<' character\\.", m -> "the value of attribute " + m.group(1) + " of <" + m.group(2) + "> runs into a '<';"
                    + " expected its closing quote before that (write a '<' inside a value as &lt;)"),
            new Translation("Attribute \"([^\"]*)\" was already specified for element \"([^\"]*)\"\\.",
                    m -> "attribute " + m.group(1) + " is given twice on <" + m.group(2) + ">; expected each attribute once"),
            new Translation("Open quote is expected for attribute \"([^\"]*)\" associated with an\\s+element type\\s+\"([^\"]*)\"\\.",
                    m -> "the value of attribute " + m.group(1) + " of <" + m.group(2) + "> has no opening quote;"
                            + " expected " + m.group(1) + "=\"...\""),
            new Translation("Attribute name \"([^\"]*)\" associated with an element type \"([^\"]*)\" must be followed by the"
                    + " ' = ' character\\.", m -> "attribute " + m.group(1) + " of <" + m.group(2) + "> has no value; expected "
                    + m.group(1) + "=\"...\""),
            new Translation("Element type \"([^\"]*)\" must be followed by either attribute specifications, \">\" or \"/>\"\\.",
                    m -> "the start tag <" + m.group(1) + " is not closed; expected attributes (name=\"value\"), > or />"),
            new Translation("The end-tag for element type \"([^\"]*)\" must end with a '>' delimiter\\.",
                    m -> "the end tag </" + m.group(1) + " is not closed; expected </" + m.group(1) + ">"),
            // The parser counts the bytes of the broken character, which tells a student nothing.
            new Translation("Invalid byte \\d of \\d-byte UTF-8 sequence\\.",
                    m -> "this is not UTF-8 text; expected a scene file saved as UTF-8 (or ASCII), not as Latin-1 or Windows-1252"),
            new Translation("An invalid XML character \\(Unicode: 0x([0-9a-fA-F]+)\\) was found in (.*)\\.",
                    m -> "character U+" + String.format(Locale.ROOT, "%04X", Integer.parseInt(m.group(1), 16))
                            + " is not allowed in XML (in " + place(m.group(2)) + "); expected printable text"),
            new Translation("The markup in the document following the root element must be well-formed\\.",
                    m -> "something follows the end of the root element; expected the file to end after </scene>"),
            new Translation("The markup in the document preceding the root element must be well-formed\\.",
                    m -> "the markup before the root element is broken; expected the file to start with <scene>"
                            + " (or an <?xml ...?> declaration)"),
            new Translation("The content of elements must consist of well-formed character data or markup\\.",
                    m -> "a '<' that starts no tag; expected a tag name after '<' (write a '<' in text as &lt;)"),
            new Translation("The string \"--\" is not permitted within comments\\.",
                    m -> "\"--\" inside a comment; expected a comment without \"--\" before its closing -->"),
            new Translation("Comment must start with \"<!--\"\\.", m -> "a comment that does not start with <!--; expected <!--"),
            new Translation("The entity name must immediately follow the '&' in the entity reference\\.",
                    m -> "a '&' that starts no entity; expected &amp; for an '&' in text"),
            new Translation("The reference to entity \"([^\"]*)\" must end with the ';' delimiter\\.",
                    m -> "the entity &" + m.group(1) + " is not ended; expected &" + m.group(1) + "; (and &amp; for a plain '&')"),
            new Translation("The entity \"([^\"]*)\" was referenced, but not declared\\.",
                    m -> "unknown entity &" + m.group(1) + ";; expected one of &lt; &gt; &amp; &quot; &apos;"),
            new Translation("XML version \"([^\"]*)\" is not supported, only XML 1\\.0 is supported\\.",
                    m -> "XML version \"" + m.group(1) + "\" is not supported; expected version=\"1.0\""),
            new Translation("Invalid encoding name \"([^\"]*)\"\\.",
                    m -> "encoding \"" + m.group(1) + "\" is not known; expected encoding=\"UTF-8\" (or no encoding)"),
            new Translation("The processing instruction target matching \"\\[xX\\]\\[mM\\]\\[lL\\]\" is not allowed\\.",
                    m -> "an <?xml ...?> declaration after the start of the file; expected it first in the file, or not at all"),
            new Translation("(.*XML declaration.*|.*encoding declaration.*|.*version.*is required.*)",
                    m -> "the <?xml ...?> declaration is broken (" + withoutFullStop(m.group(1)) + "); " + DECLARATION),
            new Translation("(.*processing instruction.*)",
                    m -> "a broken <?...?> instruction (" + withoutFullStop(m.group(1)) + "); expected <?target data?>"));

    private XmlProblems() {
    }

    /**
     * The problem, in the words a scene error uses.
     *
     * @param message     the parser's message
     * @param anyElement  whether the parser had seen any element
     * @param text        the file's text
     * @param endTag      the name in the end tag the parser stopped in, or null
     */
    static String of(String message, boolean anyElement, String text, String endTag) {
        String m = message == null ? "" : message;
        if (m.contains("DOCTYPE")) {
            return "a DOCTYPE is not allowed in a scene file; expected plain XML, without entities or external files";
        }
        Matcher unmatched = UNMATCHED_END_TAG.matcher(m);
        if (unmatched.matches()) {
            String found = endTag != null ? "</" + SceneException.excerpt(endTag) + ">" : "an end tag";
            return "malformed XML: " + found + " does not close <" + unmatched.group(1) + ">; expected </" + unmatched.group(1) + ">";
        }
        if (m.equals("Premature end of file.") && !anyElement) {
            return text.isBlank() ? "the file is empty; expected a <scene> element" : "the file has no elements; expected a <scene> element";
        }
        if (m.equals("Content is not allowed in prolog.")) {
            return "malformed XML: text before the first element;"
                    + " expected the file to start with <scene> (or an <?xml ...?> declaration)";
        }
        for (Translation t : TRANSLATIONS) {
            Matcher match = t.message.matcher(m);
            if (match.matches()) {
                return "malformed XML: " + t.problem.apply(match);
            }
        }
        return "malformed XML: " + withoutFullStop(m) + "; expected well-formed XML";
    }

    /** "the element content of the document" → "element text", and the like. */
    private static String place(String parserPlace) {
        if (parserPlace.startsWith("the element content")) {
            return "element text";
        }
        Matcher attribute = Pattern.compile("the value of attribute \"([^\"]*)\" and element is \"([^\"]*)\"").matcher(parserPlace);
        if (attribute.matches()) {
            return "the value of attribute " + attribute.group(1) + " of <" + attribute.group(2) + ">";
        }
        return parserPlace;
    }

    /** The parser's sentences end with a full stop; ours do not. */
    private static String withoutFullStop(String sentence) {
        return sentence.endsWith(".") ? sentence.substring(0, sentence.length() - 1) : sentence;
    }
}
