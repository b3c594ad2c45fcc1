package ray.testing;

import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.lang.reflect.Method;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.Test;

/**
 * The build tells bonus tests apart by name and by task: `gradle test` leaves out classes named
 * *BonusTest and the classes of extra-credit tasks, so that a finished assignment is green, and
 * `gradle bonus` runs only them. So every other shipped test class with a bonus {@link Points} must
 * be named *BonusTest and hold no regular points, and every *BonusTest must be all bonus; otherwise
 * a bonus test would turn `gradle test` red, or a regular one would drop out of it.
 */
public class BonusTestNamesTest {
    @Test
    public void shippedBonusTestsAreExactlyTheClassesNamedBonusTest() throws Exception {
        List<String> wrong = new ArrayList<>();
        int bonusClasses = 0;
        for (Class<?> type : shippedTestClasses()) {
            boolean named = type.getSimpleName().endsWith("BonusTest");
            Points onClass = type.getAnnotation(Points.class);
            boolean anyBonus = onClass != null && onClass.bonus();
            boolean anyRegular = onClass != null && !onClass.bonus();
            for (Method method : type.getMethods()) {
                Points points = method.getAnnotation(Points.class);
                if (points != null) {
                    anyBonus |= points.bonus();
                    anyRegular |= !points.bonus();
                }
            }
            if (StudentTask.ofTestClass(type).extraCredit) {
                continue; // all of an extra-credit task's tests are bonus tests, whatever their names
            }
            if (named && (anyRegular || !anyBonus)) {
                wrong.add(type.getName() + " is named *BonusTest but holds " + (anyRegular ? "regular points" : "no bonus points"));
            } else if (!named && anyBonus) {
                wrong.add(type.getName() + " holds bonus points but is not named *BonusTest");
            }
            bonusClasses += named ? 1 : 0;
        }
        assertTrue(String.join("; ", wrong), wrong.isEmpty());
        assertTrue("found no *BonusTest class among the shipped tests", bonusClasses >= 2);
    }

    /** The compiled classes of the tests under src/test/java (the instructor's tests share the class folder). */
    private static List<Class<?>> shippedTestClasses() throws IOException, URISyntaxException, ClassNotFoundException {
        Path classes = Path.of(Points.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        Path sources = Path.of("src/test/java");
        List<String> names;
        try (Stream<Path> files = Files.walk(sources)) {
            names = files.filter(p -> p.toString().endsWith("Test.java"))
                    .map(p -> sources.relativize(p).toString().replace('/', '.').replaceAll("\\.java$", ""))
                    .collect(Collectors.toList());
        }
        List<Class<?>> types = new ArrayList<>();
        for (String name : names) {
            if (Files.exists(classes.resolve(name.replace('.', '/') + ".class"))) {
                types.add(Class.forName(name));
            }
        }
        assertTrue("no compiled shipped test in " + classes, !types.isEmpty());
        return types;
    }
}
