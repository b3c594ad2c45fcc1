package ray.scene;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;

import java.util.List;
import org.junit.Test;

/** Checks the edit distance behind "did you mean": a swap of neighbouring letters is one edit, as a typo is. */
public class SuggestionsTest {
    @Test
    public void swappedNeighboursAreOneEdit() {
        assertEquals(1, Suggestions.editDistance("bleu", "blue"));
        assertEquals(1, Suggestions.editDistance("raidus", "radius"));
        assertEquals("blue", Suggestions.closest("bleu", List.of("red", "blue", "green")));
    }

    @Test
    public void insertionsDeletionsAndSubstitutionsCountOnceEach() {
        assertEquals(0, Suggestions.editDistance("blue", "blue"));
        assertEquals(1, Suggestions.editDistance("blu", "blue"));
        assertEquals(1, Suggestions.editDistance("bluee", "blue"));
        assertEquals(1, Suggestions.editDistance("blua", "blue"));
        assertEquals(3, Suggestions.editDistance("kitten", "sitting"));
        assertEquals(4, Suggestions.editDistance("", "blue"));
    }

    @Test
    public void aSwapIsNotAShortcutForLettersFarApart() {
        // "ca" to "abc" needs three edits: optimal string alignment swaps only letters that stay neighbours.
        assertEquals(3, Suggestions.editDistance("ca", "abc"));
    }

    @Test
    public void nothingCloseIsNoSuggestion() {
        assertNull(Suggestions.closest("xyz", List.of("red", "blue")));
        assertNull(Suggestions.closest("blue", List.of("blue")));
    }
}
