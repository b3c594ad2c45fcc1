package ray.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import org.junit.Test;
import ray.bvh.BrokenTree;

/** The one line a failed render prints instead of a stack trace. */
public class ErrorsTest {
    @Test
    public void aTreeTheFrameworkCannotSearchWithIsNamedAsTheStudentsTree() {
        assertEquals("your tree cannot be searched: BvhTree.build over 3 primitives: primitive 2 is in no leaf",
                Errors.oneLine(new BrokenTree("BvhTree.build over 3 primitives: primitive 2 is in no leaf")));
    }

    /** ray1 explore's page says it the same way. */
    @Test
    public void theExplorePageNamesItTheSameWay() {
        BrokenTree broken = new BrokenTree("primitive 0 has no box (null)");
        assertEquals(Errors.oneLine(broken), ray.inspect.Failure.oneLine(broken));
    }

    @Test
    public void anotherExceptionIsNamedWithWhereTheProjectsCodeThrewIt() {
        String line = Errors.oneLine(new IllegalArgumentException("radius must be positive"));
        assertTrue(line, line.startsWith("IllegalArgumentException: radius must be positive (at ErrorsTest.java:"));
        assertTrue(line, line.endsWith("; --verbose shows the stack trace)"));
    }
}
