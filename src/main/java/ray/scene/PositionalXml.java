package ray.scene;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParser;
import javax.xml.parsers.SAXParserFactory;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.xml.sax.Attributes;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.SAXNotRecognizedException;
import org.xml.sax.SAXNotSupportedException;
import org.xml.sax.SAXParseException;
import org.xml.sax.ext.DefaultHandler2;

/**
 * Reads an XML file into a DOM whose elements remember where they start, so that every later
 * error can name a line and column. A DOM parser forgets positions; SAX reports them, so SAX
 * events build the DOM here.
 *
 * <p>Hardened: a DOCTYPE is refused, so no entity can read files, reach the network or expand
 * without bound ("billion laughs").
 */
final class PositionalXml {
    private static final String POSITION = "ray1.position";

    private PositionalXml() {
    }

    static Document read(Path file) {
        byte[] bytes = FileProblems.readAllBytes(file, "a scene file", Limits.MAX_SCENE_BYTES);
        Document document;
        SAXParser parser;
        try {
            SAXParserFactory factory = SAXParserFactory.newInstance();
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            parser = factory.newSAXParser();
            document = DocumentBuilderFactory.newInstance().newDocumentBuilder().newDocument();
        } catch (SAXException | ParserConfigurationException e) {
            throw new SceneException(file, 1, 1, "cannot set up the XML parser (" + e.getMessage() + ")");
        }
        Builder builder = new Builder(document);
        try {
            try {
                // The parser's own words in a message should not depend on the computer's language: ROOT
                // picks its base messages, which are English (ENGLISH would fall back to the default language's).
                parser.setProperty("http://apache.org/xml/properties/locale", Locale.ROOT);
            } catch (SAXNotRecognizedException | SAXNotSupportedException e) {
                // Another parser than the JDK's: its messages come in the default language.
            }
            // The lexical handler reports comments, so that text after a comment is located correctly.
            parser.setProperty("http://xml.org/sax/properties/lexical-handler", builder);
            parser.parse(new ByteArrayInputStream(bytes), builder);
            return document;
        } catch (TooDeep e) {
            throw new SceneException(file, e.line, e.column, "elements are nested more than " + Limits.MAX_NESTING
                    + " deep; expected a scene of at most " + Limits.MAX_NESTING + " levels");
        } catch (SAXParseException e) {
            int line = Math.max(1, e.getLineNumber());
            int column = Math.max(1, e.getColumnNumber());
            String text = new String(bytes, StandardCharsets.UTF_8);
            if (ENDS_INSIDE_MARKUP.equals(e.getMessage()) && !builder.open.isEmpty()) {
                // A comment or CDATA section left open: point at where it starts, not at the end of the file.
                SceneException unclosed = unclosedAtEnd(file, text, "<!--", "-->", "comment");
                if (unclosed == null) {
                    unclosed = unclosedAtEnd(file, text, "<![CDATA[", "]]>", "CDATA section");
                }
                if (unclosed != null) {
                    throw unclosed;
                }
            }
            throw new SceneException(file, line, column, parseProblem(e, builder, text, line, column));
        } catch (SAXException | IOException e) {
            throw new SceneException(file, 1, 1, "cannot parse the XML (" + e.getMessage() + ")");
        }
    }

    /** What the parser says when the file ends inside an element, comment or CDATA section. */
    private static final String ENDS_INSIDE_MARKUP = "XML document structures must start and end within the same entity.";
    private static final Pattern UNMATCHED_END_TAG =
            Pattern.compile("The element type \"([^\"]*)\" must be terminated by the matching end-tag .*");
    private static final Pattern LESS_THAN_IN_ATTRIBUTE = Pattern.compile("The value of attribute \"([^\"]*)\" associated with"
            + " an element type \"([^\"]*)\" must not contain the '<' character\\.");

    /**
     * The problem the parser found, in our own words for the mistakes people make most (a misspelt or
     * missing end tag, a file cut short, a missing quote, text outside the root) and in the parser's
     * (English) words otherwise.
     */
    private static String parseProblem(SAXParseException e, Builder builder, String text, int line, int column) {
        String message = e.getMessage() == null ? "" : e.getMessage();
        if (message.contains("DOCTYPE")) {
            return "a DOCTYPE is not allowed in a scene file; expected plain XML, without entities or external files";
        }
        Matcher m = UNMATCHED_END_TAG.matcher(message);
        if (m.matches()) {
            String open = m.group(1);
            String endTag = endTagAt(text, line, column);
            return "malformed XML: " + (endTag != null ? "</" + endTag + ">" : "an end tag") + " does not close <" + open
                    + ">; expected </" + open + ">";
        }
        m = LESS_THAN_IN_ATTRIBUTE.matcher(message);
        if (m.matches()) {
            return "malformed XML: the value of attribute " + m.group(1) + " of <" + m.group(2) + "> runs into a '<'; "
                    + "expected its closing quote before that (write a '<' inside a value as &lt;)";
        }
        if (message.equals(ENDS_INSIDE_MARKUP) && !builder.open.isEmpty()) {
            String open = builder.open.peek().getTagName();
            return "malformed XML: the file ends before <" + open + "> is closed; expected </" + open + ">";
        }
        if (message.equals("Premature end of file.") && !builder.anyElement) {
            return text.isBlank() ? "the file is empty; expected a <scene> element"
                    : "the file has no elements; expected a <scene> element";
        }
        if (message.equals("Content is not allowed in prolog.")) {
            return "malformed XML: text before the first element;"
                    + " expected the file to start with <scene> (or an <?xml ...?> declaration)";
        }
        // The parser's sentences end with a full stop; ours do not.
        return "malformed XML: " + (message.endsWith(".") ? message.substring(0, message.length() - 1) : message);
    }

    /** The name in the end tag ({@code </name>}) that the parser stopped in, or null if it is not found there. */
    private static String endTagAt(String text, int line, int column) {
        String[] lines = text.split("\r\n|\r|\n", -1);
        if (line > lines.length) {
            return null;
        }
        String l = lines[line - 1];
        int start = l.lastIndexOf("</", Math.min(column - 1, l.length()));
        if (start < 0) {
            return null;
        }
        int end = start + 2;
        while (end < l.length() && l.charAt(end) != '>' && !Character.isWhitespace(l.charAt(end))) {
            end++;
        }
        return end > start + 2 ? SceneException.excerpt(l.substring(start + 2, end)) : null;
    }

    /**
     * The error for a {@code open}…{@code close} section (a comment or CDATA section) that the file
     * ends inside, located where it starts; null if the last one is closed.
     */
    private static SceneException unclosedAtEnd(Path file, String text, String open, String close, String what) {
        int start = text.lastIndexOf(open);
        if (start < 0 || text.indexOf(close, start + open.length()) >= 0) {
            return null;
        }
        int line = 1;
        int lineStart = 0;
        for (int i = 0; i < start; i++) {
            char c = text.charAt(i);
            // \r\n and \r end a line as \n does.
            if (c == '\n' || (c == '\r' && (i + 1 == text.length() || text.charAt(i + 1) != '\n'))) {
                line++;
                lineStart = i + 1;
            }
        }
        return new SceneException(file, line, start - lineStart + 1,
                "malformed XML: this " + what + " is never closed; expected " + close + " before the end of the file");
    }

    /**
     * Line and column of a node: for an element, where its start tag ends (SAX reports positions
     * there); for a text node, its first character that is not white space.
     */
    static int[] position(Node node) {
        Object p = node.getUserData(POSITION);
        return p instanceof int[] ? (int[]) p : new int[] {1, 1};
    }

    /** Thrown from the SAX handler to stop at the element that nests too deep. */
    private static final class TooDeep extends SAXException {
        final int line;
        final int column;

        TooDeep(int line, int column) {
            this.line = line;
            this.column = column;
        }
    }

    private static final class Builder extends DefaultHandler2 {
        private final Document document;
        /** The elements started and not yet ended, innermost first. */
        private final Deque<Element> open = new ArrayDeque<>();
        private boolean anyElement;
        private final StringBuilder text = new StringBuilder();
        private Locator locator;
        /** Where the next character of text starts: right after the latest tag, comment or instruction. */
        private int cursorLine = 1;
        private int cursorColumn = 1;
        /** Where the pending text's first non-blank character is, or null while it is all white space. */
        private int[] textPosition;

        Builder(Document document) {
            this.document = document;
        }

        @Override
        public void setDocumentLocator(Locator locator) {
            this.locator = locator;
        }

        @Override
        public void startElement(String uri, String localName, String qName, Attributes attributes) throws SAXException {
            flushText();
            anyElement = true;
            Element element = document.createElement(qName);
            for (int i = 0; i < attributes.getLength(); i++) {
                element.setAttribute(attributes.getQName(i), attributes.getValue(i));
            }
            element.setUserData(POSITION, new int[] {locator.getLineNumber(), locator.getColumnNumber()}, null);
            if (open.isEmpty()) {
                document.appendChild(element);
            } else {
                open.peek().appendChild(element);
            }
            open.push(element);
            if (open.size() > Limits.MAX_NESTING) {
                // Stopped here: the loader recurses once per level and would overflow its stack.
                throw new TooDeep(locator.getLineNumber(), locator.getColumnNumber());
            }
            moveCursorToLocator();
        }

        @Override
        public void endElement(String uri, String localName, String qName) {
            flushText();
            open.pop();
            moveCursorToLocator();
        }

        @Override
        public void comment(char[] ch, int start, int length) {
            moveCursorToLocator();
        }

        @Override
        public void processingInstruction(String target, String data) {
            moveCursorToLocator();
        }

        @Override
        public void startCDATA() {
            // The locator is already past the whole section here; the text starts after "<![CDATA[".
            cursorColumn += "<![CDATA[".length();
        }

        @Override
        public void characters(char[] ch, int start, int length) {
            // SAX gives no position for text, so count from the end of the preceding markup through
            // the leading white space (written literally) to the first character that is not blank.
            for (int i = start; i < start + length && textPosition == null; i++) {
                if (ch[i] == '\n') {
                    cursorLine++;
                    cursorColumn = 1;
                } else if (Character.isWhitespace(ch[i])) {
                    cursorColumn++;
                } else {
                    textPosition = new int[] {cursorLine, cursorColumn};
                }
            }
            text.append(ch, start, length);
        }

        private void moveCursorToLocator() {
            if (textPosition == null) {
                cursorLine = locator.getLineNumber();
                cursorColumn = locator.getColumnNumber();
            }
        }

        private void flushText() {
            if (text.length() > 0 && !open.isEmpty()) {
                Node node = open.peek().appendChild(document.createTextNode(text.toString()));
                if (textPosition != null) {
                    node.setUserData(POSITION, textPosition, null);
                }
            }
            text.setLength(0);
            textPosition = null;
        }
    }
}
