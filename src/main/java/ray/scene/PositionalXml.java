package ray.scene;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.UnsupportedEncodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Locale;
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
            TextPositions positions = new TextPositions(text);
            FoundEndTag endTag = FoundEndTag.at(positions, line, column);
            SceneException unclosed = Unclosed.error(file, positions, builder.open, e.getMessage(), endTag, line, column);
            if (unclosed != null) {
                throw unclosed;
            }
            throw new SceneException(file, line, column,
                    XmlProblems.of(e.getMessage(), builder.anyElement, text, endTag == null ? null : endTag.name));
        } catch (UnsupportedEncodingException e) {
            // Raised for the encoding named in <?xml ... encoding="..."?>, which is on line 1.
            throw new SceneException(file, 1, 1, "encoding \"" + SceneException.excerpt(String.valueOf(e.getMessage()))
                    + "\" is not supported; expected encoding=\"UTF-8\" (or no encoding)");
        } catch (SAXException | IOException e) {
            throw new SceneException(file, 1, 1, "cannot parse the XML (" + e.getMessage() + "); expected a well-formed XML file");
        }
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
