package ray.grading;

/**
 * The handout markers of DESIGN.md: lines from {@code // BEGIN SOLUTION} through
 * {@code // END SOLUTION} are the instructor's; a {@code // STUB: code} line is the student's
 * {@code code}. One source serves both, and both versions compile.
 */
public final class SolutionMarkers {
    public static final String BEGIN = "// BEGIN SOLUTION";
    public static final String END = "// END SOLUTION";
    public static final String STUB = "// STUB: ";

    /** The first line of a task's TODO comment, with the task's number. */
    private static final java.util.regex.Pattern TODO = java.util.regex.Pattern.compile("//\\s*TODO\\(Task (\\d+)\\)");

    private SolutionMarkers() {
    }

    /** The first line of a TODO comment's hints for one level ("// HINTS steps"), and the line after the last level's. */
    public static final String HINTS = "// HINTS ";
    public static final String END_HINTS = "// END HINTS";

    /**
     * The student's version of a file of task {@code number} in the assignment, whose hints are at
     * {@code level}: {@link #studentVersion}, with every {@code TODO(Task N)} comment numbered as the
     * assignment numbers the task, and of each TODO's hints only those of the level (every level
     * keeps the lines before the first {@code // HINTS} marker: the goal and the conventions).
     */
    public static String studentVersion(String source, String fileName, int number, ray.assignment.HintLevel level) {
        return TODO.matcher(hintsAt(studentVersion(source, fileName), level)).replaceAll("// TODO(Task " + number + ")");
    }

    /** {@code text} with each TODO's hints at {@code level} only, their markers gone. */
    static String hintsAt(String text, ray.assignment.HintLevel level) {
        StringBuilder out = new StringBuilder(text.length());
        String[] lines = text.split("\n", -1);
        String block = null;
        for (int n = 0; n < lines.length; n++) {
            String trimmed = lines[n].strip();
            if (trimmed.startsWith(HINTS)) {
                block = trimmed.substring(HINTS.length()).strip();
                continue;
            }
            if (trimmed.equals(END_HINTS)) {
                block = null;
                continue;
            }
            if (block != null && !block.equals(level.id())) {
                continue;
            }
            out.append(lines[n]);
            if (n < lines.length - 1) {
                out.append('\n');
            }
        }
        return out.toString();
    }

    /**
     * The version of a student file that ships when the assignment does not choose its task: the
     * solution kept (its markers gone), the stub lines dropped, and each TODO comment (its first line
     * and the comment lines that continue it) removed, so that nothing asks for work that is done.
     *
     * @throws IllegalArgumentException for markers that do not pair up, naming the file and line
     */
    public static String solvedVersion(String source, String fileName) {
        studentVersion(source, fileName); // the same checks of the markers
        StringBuilder out = new StringBuilder(source.length());
        String[] lines = source.split("\n", -1);
        boolean inTodo = false;
        for (int n = 0; n < lines.length; n++) {
            String trimmed = lines[n].strip();
            if (TODO.matcher(trimmed).lookingAt()) {
                inTodo = true;
                continue;
            }
            if (inTodo && trimmed.startsWith("//") && !trimmed.equals(BEGIN)) {
                continue;
            }
            inTodo = false;
            if (trimmed.equals(BEGIN) || trimmed.equals(END) || trimmed.startsWith(STUB)) {
                continue;
            }
            out.append(lines[n]);
            if (n < lines.length - 1) {
                out.append('\n');
            }
        }
        return out.toString();
    }

    /**
     * The student's version of a source file: solution blocks removed, stub lines uncommented
     * (keeping their indentation), each TODO's hints at every level still in their markers
     * ({@link #studentVersion(String, String, int, ray.assignment.HintLevel)} picks one).
     *
     * @throws IllegalArgumentException for markers that do not pair up, naming the file and line
     */
    public static String studentVersion(String source, String fileName) {
        StringBuilder out = new StringBuilder(source.length());
        boolean inSolution = false;
        int beganAt = 0;
        String[] lines = source.split("\n", -1);
        for (int n = 0; n < lines.length; n++) {
            String line = lines[n];
            String trimmed = line.strip();
            if (trimmed.equals(BEGIN)) {
                if (inSolution) {
                    throw new IllegalArgumentException(fileName + ":" + (n + 1) + ": " + BEGIN + " inside the block begun at line " + beganAt);
                }
                inSolution = true;
                beganAt = n + 1;
                continue;
            }
            if (trimmed.equals(END)) {
                if (!inSolution) {
                    throw new IllegalArgumentException(fileName + ":" + (n + 1) + ": " + END + " without " + BEGIN);
                }
                inSolution = false;
                continue;
            }
            if (inSolution) {
                continue;
            }
            if (trimmed.startsWith(STUB)) {
                String indent = line.substring(0, line.indexOf(STUB));
                line = indent + trimmed.substring(STUB.length());
            }
            out.append(line);
            if (n < lines.length - 1) {
                out.append('\n');
            }
        }
        if (inSolution) {
            throw new IllegalArgumentException(fileName + ":" + beganAt + ": " + BEGIN + " is never ended");
        }
        return out.toString();
    }
}
