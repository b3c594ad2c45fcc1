package ray.scene;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;

import org.junit.Test;

/** Checks line and column counting as the XML parser does it: "\n", "\r\n" and a lone "\r" end a line. */
public class TextPositionsTest {
    private final TextPositions positions = new TextPositions("ab\ncd\r\nef\rgh");

    @Test
    public void everyKindOfLineEndStartsALine() {
        assertArrayEquals(new int[] {1, 1}, positions.position(0));
        assertArrayEquals(new int[] {1, 3}, positions.position(2));
        assertArrayEquals(new int[] {2, 2}, positions.position(4));
        assertArrayEquals(new int[] {3, 1}, positions.position(7));
        assertArrayEquals(new int[] {4, 2}, positions.position(11));
    }

    @Test
    public void offsetIsTheInverseOfPosition() {
        for (int offset = 0; offset < positions.text().length(); offset++) {
            char c = positions.text().charAt(offset);
            if (c != '\n' && c != '\r') {
                int[] p = positions.position(offset);
                assertEquals("offset " + offset, offset, positions.offset(p[0], p[1]));
            }
        }
    }

    @Test
    public void columnPastTheLineStopsAtItsEndAndLinePastTheTextAtTheTextsEnd() {
        assertEquals(5, positions.offset(2, 99));
        assertEquals(12, positions.offset(9, 1));
    }

    @Test
    public void byteOrderMarkIsNotCounted() {
        TextPositions marked = new TextPositions("\uFEFF<a>");
        assertEquals("<a>", marked.text());
        assertArrayEquals(new int[] {1, 1}, marked.position(0));
    }
}
