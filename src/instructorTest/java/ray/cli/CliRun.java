package ray.cli;

import static org.junit.Assert.assertFalse;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

/** One run of {@link Ray1Command} with its standard output and error captured, plus scene-file helpers. */
final class CliRun {
    final int status;
    final String out;
    final String err;

    private CliRun(int status, String out, String err) {
        this.status = status;
        this.out = out;
        this.err = err;
    }

    static CliRun of(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status;
        try (PrintWriter o = new PrintWriter(out); PrintWriter e = new PrintWriter(err)) {
            status = Ray1Command.run(o, e, args);
        }
        return new CliRun(status, out.toString(), err.toString());
    }

    /** Non-empty lines of a captured stream. */
    static String[] lines(String text) {
        return text.lines().filter(l -> !l.isBlank()).toArray(String[]::new);
    }

    /** Users should see one-line messages, never a Java stack trace. */
    void assertNoStackTrace() {
        for (String text : new String[] {out, err}) {
            assertFalse("stack trace in:\n" + text, text.contains("\tat ") || text.contains("Caused by:")
                    || text.matches("(?s).*\\bat (java|ray|picocli)\\..*"));
        }
    }

    @Override
    public String toString() {
        return "status " + status + "\n--- out:\n" + out + "--- err:\n" + err;
    }

    /**
     * A 4×4 scene: an orthographic view of [−2, 2]² looking down at a white Lambertian floor lit by one
     * light, so every one of the 16·n² camera rays hits and traces one shadow ray.
     */
    static String floorScene(String extra) {
        return "<?xml version=\"1.0\"?>\n"
                + "<scene>\n"
                + "  <camera type=\"OrthographicCamera\">\n"
                + "    <viewPoint>0 0 5</viewPoint>\n"
                + "    <viewWidth>4</viewWidth>\n"
                + "    <viewHeight>4</viewHeight>\n"
                + "  </camera>\n"
                + "  <image>4 4</image>\n"
                + extra
                + "  <light><position>-1.5 -0.5 2</position><intensity>4 4 4</intensity></light>\n"
                + "  <surface type=\"Triangle\">\n"
                + "    <v0>-40 -40 0</v0> <v1>40 -40 0</v1> <v2>0 40 0</v2>\n"
                + "  </surface>\n"
                + "</scene>\n";
    }

    /**
     * For {@link #floorScene}'s {@code extra}: a box given with minPt.y above maxPt.y, which loads
     * with a warning at line 9, column 23 ({@link #upsideDownBoxWarning}); it lies below the floor,
     * out of view and out of the light, so the image is the floor's alone.
     */
    static final String UPSIDE_DOWN_BOX = "  <surface type=\"Box\"><minPt>5 5 -3</minPt><maxPt>6 4 -2</maxPt></surface>\n";

    /** The warning line of {@link #UPSIDE_DOWN_BOX} in the floor scene {@code file}. */
    static String upsideDownBoxWarning(Path file) {
        return file + ":9:23: warning: Box minPt.y > maxPt.y; built from the corners as given, as the course's renderer does";
    }

    /** A scene whose error is on line 5: a sphere with a negative radius. */
    static final String BROKEN_SCENE = "<scene>\n"
            + "  <camera type=\"OrthographicCamera\"/>\n"
            + "  <image>4 4</image>\n"
            + "  <surface type=\"Sphere\">\n"
            + "    <radius>-1</radius>\n"
            + "  </surface>\n"
            + "</scene>\n";

    static Path write(Path file, String text) throws IOException {
        Files.createDirectories(file.getParent());
        return Files.writeString(file, text);
    }
}
