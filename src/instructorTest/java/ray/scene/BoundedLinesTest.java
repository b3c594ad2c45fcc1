package ray.scene;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertThrows;

import java.io.FilterReader;
import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import org.junit.Test;

/** Lines as BufferedReader.readLine splits them, whatever blocks the text arrives in, and never longer than the limit. */
public class BoundedLinesTest {
    private static List<String> lines(Reader in, int maxLength) throws Exception {
        BoundedLines lines = new BoundedLines(in, maxLength);
        List<String> out = new ArrayList<>();
        for (String line = lines.next(); line != null; line = lines.next()) {
            out.add(line);
        }
        assertNull("the end stays the end", lines.next());
        return out;
    }

    /** A reader that hands out at most one char per read, so that every line end falls between blocks. */
    private static Reader oneCharAtATime(String text) {
        return new FilterReader(new StringReader(text)) {
            @Override
            public int read(char[] buffer, int offset, int length) throws IOException {
                return super.read(buffer, offset, Math.min(1, length));
            }
        };
    }

    @Test
    public void everyLineEndSplitsAsReadLineDoes() throws Exception {
        String text = "a\nbb\r\nccc\rd\n\n\r\re\r";
        List<String> expected = List.of("a", "bb", "ccc", "d", "", "", "", "e");
        assertEquals(expected, new java.io.BufferedReader(new StringReader(text)).lines().collect(java.util.stream.Collectors.toList()));
        assertEquals(expected, lines(new StringReader(text), 10));
        assertEquals(expected, lines(oneCharAtATime(text), 10));
        assertEquals(List.of("x"), lines(new StringReader("x\r\n"), 10));
        assertEquals(List.of(), lines(new StringReader(""), 10));
    }

    @Test
    public void aReturnAndItsNewlineInDifferentBlocksAreOneLineEnd() throws Exception {
        // The 8192-char buffer ends right after the "\r".
        String first = "x".repeat(8191) + "\r";
        assertEquals(List.of("x".repeat(8191), "y"), lines(new StringReader(first + "\ny"), 10_000));
    }

    @Test
    public void aLineOfExactlyTheLimitIsReadAndOneCharMoreIsRefused() throws Exception {
        assertEquals(List.of("12345", "6"), lines(oneCharAtATime("12345\n6"), 5));
        BoundedLines tooLong = new BoundedLines(new StringReader("ok\n123456\n"), 5);
        assertEquals("ok", tooLong.next());
        assertThrows(BoundedLines.TooLong.class, tooLong::next);
    }
}
