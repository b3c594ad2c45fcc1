package ray.scene;

import static org.junit.Assert.assertEquals;

import java.nio.file.Path;
import org.junit.Test;

/** An error stays one printable line whatever text it quotes from a damaged file. */
public class SceneExceptionTest {
    @Test
    public void lineBreaksAndControlCharactersInAProblemAreWrittenAsEscapes() {
        SceneException e = new SceneException(Path.of("s.xml"), 2, 5, "bad name \"UTF\n8\r\t\u001b[2J\"; expected UTF-8");
        assertEquals("s.xml:2:5: bad name \"UTF\\n8\\r\\t\\u001b[2J\"; expected UTF-8", e.getMessage());
        assertEquals("bad name \"UTF\\n8\\r\\t\\u001b[2J\"; expected UTF-8", e.problem());
    }

    @Test
    public void printableTextIsKeptAsItIs() {
        SceneException e = new SceneException(Path.of("dir/s.xml"), 1, 1, "größe \"π\" is not a number; expected a number");
        assertEquals("dir/s.xml:1:1: größe \"π\" is not a number; expected a number", e.getMessage());
    }
}
