package ray.tools;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import ray.assignment.Assignment;
import ray.assignment.HintLevel;
import ray.assignment.Task;

/**
 * The students' Markdown (README.md, docs/*.md) as the handout ships it for an assignment. The
 * sources are written for the default preset ({@value Assignment#DEFAULT_PRESET}), whose numbers
 * they use; for another assignment:
 * <ul>
 * <li>every task number ("Task 2", "Tasks 2 and 3", "TODO(Task 2)", "-Ptask=2") becomes the
 * assignment's number of that task;</li>
 * <li>a task's section, from a line {@code <!-- TASK id -->} to {@code <!-- END TASK -->}, ships
 * only when the task is chosen, and a run of such sections (blank lines between them) is put in the
 * assignment's order;</li>
 * <li>a block from {@code <!-- IF TASK id, id… -->} (or {@code <!-- IF NOT TASK id, id… -->}) to
 * {@code <!-- END IF -->} ships only when one of the tasks is (or none is) chosen, and so does a single line
 * that ends with {@code <!-- task: id -->} (a table row, a list item), a run of such lines in the
 * assignment's order;</li>
 * <li>inside a task's section, a block from {@code <!-- IF HINTS goal, steps -->} to
 * {@code <!-- END IF -->} ships only when the task's hint level is one of those named;</li>
 * <li>a block from {@code <!-- TABLE scenes -->} to {@code <!-- END TABLE -->} is replaced by the
 * table the composer writes from the table of tasks (the chosen tasks' graded scenes);</li>
 * <li>a number of a task the assignment leaves out, outside such a block, is an error naming the
 * file and line: the docs would name a task that students do not have.</li>
 * </ul>
 * The markers are removed.
 */
public final class AssignmentDocs {
    private static final Pattern SECTION = Pattern.compile("\\s*<!--\\s*TASK ([\\w-]+)\\s*-->\\s*");
    private static final Pattern SECTION_END = Pattern.compile("\\s*<!--\\s*END TASK\\s*-->\\s*");
    private static final Pattern IF = Pattern.compile("\\s*<!--\\s*IF (NOT )?TASK ([\\w-]+(?:\\s*,\\s*[\\w-]+)*)\\s*-->\\s*");
    private static final Pattern IF_END = Pattern.compile("\\s*<!--\\s*END IF\\s*-->\\s*");
    /** A table the composer writes from the table of tasks: {@code <!-- TABLE scenes -->} … {@code <!-- END TABLE -->}. */
    private static final Pattern TABLE = Pattern.compile("\\s*<!--\\s*TABLE ([a-z]+)\\s*-->\\s*");
    private static final Pattern TABLE_END = Pattern.compile("\\s*<!--\\s*END TABLE\\s*-->\\s*");
    /** Inside a task's section: a block for some of the hint levels ({@code <!-- IF HINTS goal, steps -->}). */
    private static final Pattern IF_HINTS = Pattern.compile("\\s*<!--\\s*IF HINTS ([a-z]+(?:\\s*,\\s*[a-z]+)*)\\s*-->\\s*");
    private static final Pattern LINE_TASK = Pattern.compile("\\s*<!--\\s*task: ([\\w-]+)\\s*-->\\s*$");
    /** "Task 2", "Tasks 2 and 3", "Tasks 1, 2 or 4", "TODO(Task 2)", "-Ptask=2". */
    private static final Pattern NUMBERS = Pattern.compile("\\b(Tasks? )(\\d+)((?:(?:, | and | or | to )\\d+\\b)*)|(-Ptask=)(\\d+)");
    private static final Pattern NUMBER = Pattern.compile("\\d+");
    /**
     * A task the default preset leaves out, named by its id where its number goes: "Task [lighting]",
     * "TODO(Task [lighting])", "-Ptask=[lighting]" become that task's number in the assignment.
     */
    private static final Pattern BY_ID = Pattern.compile("(Task |-Ptask=)\\[([\\w-]+)\\]");

    private AssignmentDocs() {
    }

    /** {@code markdown} (the file {@code fileName}) as it ships for {@code assignment}. */
    public static String compose(String markdown, String fileName, Assignment assignment) {
        Composer composer = new Composer(fileName, Assignment.preset(Assignment.DEFAULT_PRESET), assignment);
        return String.join("\n", composer.lines(List.of(markdown.split("\n", -1)), 0, null));
    }

    /** One file's composition; line numbers in errors count from 1. */
    private static final class Composer {
        private final String fileName;
        private final Assignment canonical;
        private final Assignment assignment;

        Composer(String fileName, Assignment canonical, Assignment assignment) {
            this.fileName = fileName;
            this.canonical = canonical;
            this.assignment = assignment;
        }

        /**
         * {@code lines}, the first of which is line {@code offset} (from 0) of the file, composed;
         * {@code section} is the task whose section they are in, or null.
         */
        List<String> lines(List<String> lines, int offset, String section) {
            List<String> out = new ArrayList<>();
            int n = 0;
            while (n < lines.size()) {
                String line = lines.get(n);
                if (SECTION.matcher(line).matches()) {
                    // A run of task sections: each kept or dropped, the kept ones in the assignment's order.
                    List<Section> run = new ArrayList<>();
                    while (n < lines.size() && (SECTION.matcher(lines.get(n)).matches() || (lines.get(n).isBlank() && nextIsSection(lines, n)))) {
                        if (lines.get(n).isBlank()) {
                            n++;
                            continue;
                        }
                        Matcher m = SECTION.matcher(lines.get(n));
                        m.matches();
                        String id = known(m.group(1), offset + n);
                        int begin = ++n;
                        n = end(lines, n, SECTION, SECTION_END, offset + begin, "TASK " + id, "<!-- END TASK -->");
                        run.add(new Section(id, offset + begin, lines.subList(begin, n)));
                        n++;
                    }
                    for (Section sec : chosenInOrder(run)) {
                        out.addAll(lines(sec.lines, sec.firstLine, sec.id));
                        out.add("");
                    }
                    continue;
                }
                Matcher table = TABLE.matcher(line);
                if (table.matches()) {
                    int begin = ++n;
                    n = end(lines, n, TABLE, TABLE_END, offset + begin, "TABLE " + table.group(1), "<!-- END TABLE -->");
                    out.addAll(generated(table.group(1), offset + begin));
                    n++;
                    continue;
                }
                Matcher levels = IF_HINTS.matcher(line);
                if (levels.matches()) {
                    if (section == null) {
                        throw new IllegalArgumentException(fileName + ":" + (offset + n + 1) + ": IF HINTS outside a task's section");
                    }
                    boolean keep = false;
                    for (String id : levels.group(1).split("\\s*,\\s*")) {
                        HintLevel level = HintLevel.of(id);
                        if (level == null) {
                            throw new IllegalArgumentException(fileName + ":" + (offset + n + 1) + ": no hint level \"" + id
                                    + "\"; expected goal, steps or formulas");
                        }
                        keep |= assignment.hints(section) == level;
                    }
                    int begin = ++n;
                    n = end(lines, n, IF_HINTS, IF_END, offset + begin, "IF HINTS " + levels.group(1), "<!-- END IF -->");
                    if (keep) {
                        out.addAll(lines(lines.subList(begin, n), offset + begin, section));
                    }
                    n++;
                    continue;
                }
                Matcher condition = IF.matcher(line);
                if (condition.matches()) {
                    boolean anyChosen = false;
                    for (String id : condition.group(2).split("\\s*,\\s*")) {
                        anyChosen |= assignment.isChosen(known(id, offset + n));
                    }
                    boolean keep = anyChosen != (condition.group(1) != null);
                    int begin = ++n;
                    n = end(lines, n, IF, IF_END, offset + begin, "IF TASK " + condition.group(2), "<!-- END IF -->");
                    if (keep) {
                        out.addAll(lines(lines.subList(begin, n), offset + begin, section));
                    }
                    n++;
                    continue;
                }
                if (SECTION_END.matcher(line).matches() || IF_END.matcher(line).matches()) {
                    throw new IllegalArgumentException(fileName + ":" + (offset + n + 1) + ": an END without its beginning");
                }
                if (LINE_TASK.matcher(line).find()) {
                    // A run of lines that each end with a task's marker (table rows, list items): the
                    // chosen tasks' lines, in the assignment's order.
                    List<Section> run = new ArrayList<>();
                    for (; n < lines.size(); n++) {
                        Matcher lineTask = LINE_TASK.matcher(lines.get(n));
                        if (!lineTask.find()) {
                            break;
                        }
                        run.add(new Section(known(lineTask.group(1), offset + n), offset + n, List.of(lines.get(n).substring(0, lineTask.start()))));
                    }
                    for (Section marked : chosenInOrder(run)) {
                        out.add(renumber(marked.lines.get(0), marked.firstLine));
                    }
                    continue;
                }
                out.add(renumber(line, offset + n));
                n++;
            }
            return out;
        }

        /** Of a run of task sections or task lines, the chosen tasks', in the assignment's order (a task's own in the run's). */
        private List<Section> chosenInOrder(List<Section> run) {
            List<Section> chosen = new ArrayList<>();
            for (Section section : run) {
                if (assignment.isChosen(section.id)) {
                    chosen.add(section);
                }
            }
            chosen.sort(Comparator.comparingInt(section -> assignment.number(section.id)));
            return chosen;
        }

        /**
         * The rows of a generated table: {@code scenes}, each chosen task's graded scenes under its
         * number and title (docs/grading.md), its header first.
         */
        private List<String> generated(String name, int n) {
            if (!name.equals("scenes")) {
                throw new IllegalArgumentException(fileName + ":" + n + ": no table \"" + name + "\"; the composer writes: scenes");
            }
            List<String> rows = new ArrayList<>(List.of("| task | scenes |", "| --- | --- |"));
            for (Task task : assignment.tasks()) {
                if (task.scenes().isEmpty()) {
                    continue;
                }
                boolean extra = assignment.isExtraCredit(task.id());
                rows.add("| Task " + assignment.number(task.id()) + " (" + task.title() + (extra ? ", extra credit" : "") + ") | "
                        + String.join(", ", task.scenes()) + (extra ? " (bonus points: a failure costs nothing)" : "") + " |");
            }
            return rows;
        }

        /** The index of the line that ends the block whose content begins at {@code n}, blocks of the same kind nested inside counted. */
        private int end(List<String> lines, int n, Pattern begins, Pattern ends, int beganAt, String what, String endMarker) {
            int depth = 0;
            for (; n < lines.size(); n++) {
                // Both kinds of IF end with END IF, so either opens a level.
                if (begins.matcher(lines.get(n)).matches() || (ends == IF_END && (IF.matcher(lines.get(n)).matches()
                        || IF_HINTS.matcher(lines.get(n)).matches()))) {
                    depth++;
                } else if (ends.matcher(lines.get(n)).matches()) {
                    if (depth == 0) {
                        return n;
                    }
                    depth--;
                }
            }
            throw new IllegalArgumentException(fileName + ":" + beganAt + ": " + what + " is never ended (" + endMarker + ")");
        }

        private String known(String id, int n) {
            if (assignment.table().find(id).isEmpty()) {
                throw new IllegalArgumentException(fileName + ":" + (n + 1) + ": there is no task \"" + id + "\" in the table of tasks");
            }
            return id;
        }

        /** The line with each task number of the default preset made the assignment's. */
        private String renumber(String line, int n) {
            Matcher m = NUMBERS.matcher(line);
            StringBuilder out = new StringBuilder();
            while (m.find()) {
                String replaced;
                if (m.group(4) != null) {
                    replaced = m.group(4) + number(m.group(5), line, n);
                } else {
                    StringBuilder list = new StringBuilder(m.group(1)).append(number(m.group(2), line, n));
                    Matcher rest = NUMBER.matcher(m.group(3));
                    int at = 0;
                    while (rest.find()) {
                        list.append(m.group(3), at, rest.start()).append(number(rest.group(), line, n));
                        at = rest.end();
                    }
                    replaced = list.toString();
                }
                m.appendReplacement(out, Matcher.quoteReplacement(replaced));
            }
            m.appendTail(out);
            Matcher byId = BY_ID.matcher(out.toString());
            StringBuilder named = new StringBuilder();
            while (byId.find()) {
                String id = known(byId.group(2), n);
                int number = assignment.number(id);
                if (number == 0) {
                    throw new IllegalArgumentException(fileName + ":" + (n + 1) + ": names Task [" + id + "], which this assignment leaves out;"
                            + " put it in an <!-- IF TASK " + id + " --> block: " + line.strip());
                }
                byId.appendReplacement(named, Matcher.quoteReplacement(byId.group(1) + number));
            }
            byId.appendTail(named);
            return named.toString();
        }

        private int number(String canonicalNumber, String line, int n) {
            Optional<Task> task = canonical.task(Integer.parseInt(canonicalNumber));
            if (task.isEmpty()) {
                throw new IllegalArgumentException(fileName + ":" + (n + 1) + ": Task " + canonicalNumber + " is no task of the "
                        + Assignment.DEFAULT_PRESET + " preset, whose numbers the docs use: " + line.strip());
            }
            int number = assignment.number(task.get().id());
            if (number == 0) {
                throw new IllegalArgumentException(fileName + ":" + (n + 1) + ": names Task " + canonicalNumber + " (" + task.get().id()
                        + "), which this assignment leaves out; put it in an <!-- IF TASK " + task.get().id() + " --> block: " + line.strip());
            }
            return number;
        }
    }

    private static boolean nextIsSection(List<String> lines, int n) {
        int next = n;
        while (next < lines.size() && lines.get(next).isBlank()) {
            next++;
        }
        return next < lines.size() && SECTION.matcher(lines.get(next)).matches();
    }

    /** A task's lines: a section, or a line with a task's marker, with where it began in the file (from 0). */
    private static final class Section {
        final String id;
        final int firstLine;
        final List<String> lines;

        Section(String id, int firstLine, List<String> lines) {
            this.id = id;
            this.firstLine = firstLine;
            this.lines = lines;
        }
    }
}
