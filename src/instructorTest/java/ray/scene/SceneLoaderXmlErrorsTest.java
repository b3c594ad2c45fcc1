package ray.scene;

import static org.junit.Assert.assertFalse;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * Checks errors in the XML itself: malformed markup, the wrong root, text where elements belong,
 * missing, empty or unreadable files and folders, and the refusal of any DOCTYPE (so no entity can
 * expand without bound or read a local file). Each error is checked whole: the file, the line and
 * column, the problem and what was expected.
 *
 * <p>SAX locates an element where its start tag ends, so an element's column is the one just after
 * its {@code >}; each element sits on its own line so that the line is unambiguous.
 */
public class SceneLoaderXmlErrorsTest {
    private static final String DOCTYPE_REFUSED =
            "a DOCTYPE is not allowed in a scene file; expected plain XML, without entities or external files";

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void mismatchedEndTagIsMalformedXmlAtThatTag() {
        Path file = SceneFixtures.write(folder, "bad.xml", """
                <scene>
                  <camera type="PerspectiveCamera">
                  </camra>
                </scene>
                """);
        // The parser stops inside "</camra>" (columns 3 to 10 of line 3).
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 3, 5,
                "malformed XML: </camra> does not close <camera>; expected </camera>");
    }

    @Test
    public void unclosedAttributeQuoteIsMalformedXmlWhereTheParserNotices() {
        Path file = SceneFixtures.write(folder, "bad.xml", """
                <scene>
                  <camera type="PerspectiveCamera/>
                  <image>4 3</image>
                </scene>
                """);
        // The quote opened on line 2 runs on into line 3, where the parser stops at the "<" of "<image>".
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 3, 3, "malformed XML: the value of attribute type of"
                + " <camera> runs into a '<'; expected its closing quote before that (write a '<' inside a value as &lt;)");
    }

    @Test
    public void truncatedFileIsMalformedXml() {
        Path file = SceneFixtures.write(folder, "bad.xml", """
                <scene>
                  <camera type="PerspectiveCamera"/>
                """);
        // Located at the <scene> left open; the parser noticed at the end of the file, after the last newline.
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 1, 1,
                "malformed XML: <scene> is never closed (the file ends at 3:1); expected </scene> before the end of the file");
    }

    @Test
    public void unclosedCommentIsReportedWhereItStarts() {
        Path file = SceneFixtures.write(folder, "bad.xml", """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <!-- the image size comes later
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 3, 3,
                "malformed XML: this comment is never closed; expected --> before the end of the file");
    }

    @Test
    public void textBeforeTheRootIsMalformedXml() {
        Path file = SceneFixtures.write(folder, "bad.xml", """
                scene:
                <scene>
                </scene>
                """);
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 1, 1,
                "malformed XML: text before the first element; expected the file to start with <scene>"
                + " (or an <?xml ...?> declaration)");
    }

    @Test
    public void bareAmpersandAsksForItsEntity() {
        Path file = SceneFixtures.write(folder, "bad.xml", """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 & 3</image>
                </scene>
                """);
        // The parser stops just past the '&' in column 12.
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 3, 13,
                "malformed XML: a '&' that starts no entity; expected &amp; for an '&' in text");
    }

    @Test
    public void attributeGivenTwiceIsReportedOnItsElement() {
        Path file = SceneFixtures.write(folder, "bad.xml", """
                <scene>
                  <camera type="PerspectiveCamera" type="OrthographicCamera"/>
                  <image>4 3</image>
                </scene>
                """);
        // Located where the start tag ends, as every element is.
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 2, 61,
                "malformed XML: attribute type is given twice on <camera>; expected each attribute once");
    }

    @Test
    public void bytesThatAreNotUtf8AreReportedWhereTheyAre() throws Exception {
        Path file = folder.getRoot().toPath().resolve("latin1.xml");
        java.nio.file.Files.write(file, "<scene>\n  <image>4 3</image> <!-- gr\u00f6\u00dfe -->\n</scene>\n"
                .getBytes(java.nio.charset.StandardCharsets.ISO_8859_1));
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 2, 29,
                "malformed XML: this is not UTF-8 text; expected a scene file saved as UTF-8 (or ASCII), not as Latin-1 or Windows-1252");
    }

    @Test
    public void controlCharacterInTextIsNamedByItsCodePoint() {
        Path file = SceneFixtures.write(folder, "bad.xml", "<scene>\n  <image>4\u0001 3</image>\n</scene>\n");
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 2, 11,
                "malformed XML: character U+0001 is not allowed in XML (in element text); expected printable text");
    }

    @Test
    public void otherMalformedXmlKeepsTheParsersEnglishWords() {
        // A rare mistake keeps the words of the JDK's parser, which the loader asks for in English.
        Path file = SceneFixtures.write(folder, "bad.xml", """
                <?xml version="1.0" standalone="maybe"?>
                <scene/>
                """);
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 1, 39, "malformed XML: The standalone document declaration"
                + " value must be \"yes\" or \"no\", not \"maybe\"; expected well-formed XML");
    }

    @Test
    public void emptyFileIsReportedAsEmpty() {
        Path file = SceneFixtures.write(folder, "empty.xml", "");
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 1, 1, "the file is empty; expected a <scene> element");
    }

    @Test
    public void fileWithoutElementsIsReportedAsSuch() {
        Path file = SceneFixtures.write(folder, "bad.xml", "<?xml version=\"1.0\"?>\n<!-- nothing yet -->\n");
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 3, 1,
                "the file has no elements; expected a <scene> element");
    }

    @Test
    public void missingFileIsReportedWithItsName() {
        Path file = folder.getRoot().toPath().resolve("nowhere.xml");
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 1, 1, "no such file; expected the path of a scene file");
    }

    @Test
    public void folderIsNotASceneFile() throws Exception {
        Path scenes = Files.createDirectories(folder.getRoot().toPath().resolve("scenes.xml"));
        SceneFixtures.assertError(SceneFixtures.loadError(scenes), scenes, 1, 1, "this is a folder; expected a scene file");
    }

    @Test
    public void unreadableFileIsReportedAsSuch() throws Exception {
        Path file = SceneFixtures.write(folder, "locked.xml", "<scene/>\n");
        String reason = SceneFixtures.makeUnreadable(file);
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 1, 1,
                "the file cannot be read (" + reason + "); expected a readable scene file");
    }

    @Test
    public void rootOtherThanSceneIsRefused() {
        Path file = SceneFixtures.write(folder, "bad.xml", """
                <?xml version="1.0"?>
                <scenery>
                </scenery>
                """);
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 2, 10, "the root element is <scenery>; expected <scene>");
    }

    @Test
    public void textAmongElementsIsReportedWhereTheTextStarts() {
        Path file = SceneFixtures.write(folder, "bad.xml", """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  radius 2
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 3, 3,
                "unexpected text \"radius 2\" in <scene>; expected only elements here");
    }

    @Test
    public void textOverSeveralLinesIsQuotedOnOneLineAndCut() {
        Path file = SceneFixtures.write(folder, "bad.xml", """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  radius 2
                  center 0 0 -5
                  and a very long sentence after that
                  <image>4 3</image>
                </scene>
                """);
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 3, 3,
                "unexpected text \"radius 2 center 0 0 -5 and a very lon...\" in <scene>; expected only elements here");
    }

    @Test
    public void textAfterAPropertyIsReportedWhereTheTextStarts() {
        Path file = SceneFixtures.write(folder, "bad.xml", """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Sphere">
                    <radius>1</radius> oops
                  </surface>
                </scene>
                """);
        // "    <radius>1</radius> " is 23 characters, so "oops" starts in column 24.
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 5, 24,
                "unexpected text \"oops\" in <surface>; expected only elements here");
    }

    @Test
    public void textAfterACommentAndTabsIsLocatedPastThem() {
        Path file = SceneFixtures.write(folder, "bad.xml", "<scene>\n  <!-- a comment\n  over two lines -->\n\t\tstray\n</scene>\n");
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 4, 3,
                "unexpected text \"stray\" in <scene>; expected only elements here");
    }

    @Test
    public void textInACdataSectionIsLocatedInsideIt() {
        Path file = SceneFixtures.write(folder, "bad.xml", "<scene>\n  <![CDATA[  stray ]]>\n</scene>\n");
        // "  <![CDATA[  " is 13 characters.
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 2, 14,
                "unexpected text \"stray\" in <scene>; expected only elements here");
    }

    @Test
    public void propertyHoldingElementsIsRefused() {
        Path file = SceneFixtures.write(folder, "bad.xml", """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                  <surface type="Sphere">
                    <radius>
                      <value>1</value>
                    </radius>
                  </surface>
                </scene>
                """);
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 5, 13, "<radius> holds elements; expected only a value");
    }

    @Test(timeout = 10_000)
    public void billionLaughsFailsFastOnItsDoctype() {
        // Ten levels of ten references each would expand to 10¹⁰ "lol"s if the parser took the DOCTYPE.
        StringBuilder xml = new StringBuilder("<?xml version=\"1.0\"?>\n<!DOCTYPE scene [\n  <!ENTITY lol0 \"lol\">\n");
        for (int level = 1; level <= 10; level++) {
            xml.append("  <!ENTITY lol").append(level).append(" \"");
            for (int k = 0; k < 10; k++) {
                xml.append("&lol").append(level - 1).append(';');
            }
            xml.append("\">\n");
        }
        xml.append("]>\n<scene>\n  <exposure>&lol10;</exposure>\n</scene>\n");
        Path file = SceneFixtures.write(folder, "lol.xml", xml.toString());
        // Located at "<!DOCTYPE" on line 2, just past the keyword.
        SceneFixtures.assertError(SceneFixtures.loadError(file), file, 2, 10, DOCTYPE_REFUSED);
    }

    @Test
    public void externalEntityIsRefusedAndTheFileItNamesNeverAppears() {
        Path secret = SceneFixtures.write(folder, "secret.txt", "TOP-SECRET-42");
        Path file = SceneFixtures.write(folder, "xxe.xml", "<?xml version=\"1.0\"?>\n"
                + "<!DOCTYPE scene [\n"
                + "  <!ENTITY secret SYSTEM \"" + secret.toUri() + "\">\n"
                + "]>\n"
                + "<scene>\n"
                + "  <camera type=\"PerspectiveCamera\"/>\n"
                + "  <image>4 3</image>\n"
                // Were the entity expanded, the secret would come back in the "not a number" error.
                + "  <exposure>&secret;</exposure>\n"
                + "</scene>\n");
        SceneException e = SceneFixtures.loadError(file);
        SceneFixtures.assertError(e, file, 2, 10, DOCTYPE_REFUSED);
        assertFalse(e.getMessage(), e.getMessage().contains("TOP-SECRET"));
    }
}
