package ray.fuzz;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Where the elements, attributes and numbers of a scene file's text are, found by a tolerant scan
 * rather than a parser: after an earlier mutation the text may no longer be XML, and the fuzzer
 * still has to find something to mutate in it.
 */
final class Markup {
    private static final Pattern TAG = Pattern.compile("<(/?)([A-Za-z_][\\w.-]*)([^<>]*?)(/?)>");
    private static final Pattern ATTRIBUTE = Pattern.compile("\\s[A-Za-z_][\\w.-]*\\s*=\\s*\"[^\"]*\"");
    private static final Pattern NUMBER = Pattern.compile("[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?");

    /** A half-open range [start, end) of the text. */
    static final class Span {
        final int start;
        final int end;

        Span(int start, int end) {
            this.start = start;
            this.end = end;
        }
    }

    private Markup() {
    }

    /**
     * Every element, from the start of its start tag to the end of its end tag (or its empty tag);
     * an end tag that matches no open start tag is skipped, and so is an element left open.
     */
    static List<Span> elements(String text) {
        List<Span> spans = new ArrayList<>();
        Deque<Integer> open = new ArrayDeque<>();
        Deque<String> names = new ArrayDeque<>();
        Matcher m = TAG.matcher(text);
        while (m.find()) {
            boolean end = !m.group(1).isEmpty();
            boolean empty = !m.group(4).isEmpty();
            if (empty && !end) {
                spans.add(new Span(m.start(), m.end()));
            } else if (!end) {
                open.push(m.start());
                names.push(m.group(2));
            } else if (!names.isEmpty() && names.peek().equals(m.group(2))) {
                names.pop();
                spans.add(new Span(open.pop(), m.end()));
            }
        }
        return spans;
    }

    /** Every attribute of a start tag, with the white space before it. */
    static List<Span> attributes(String text) {
        List<Span> spans = new ArrayList<>();
        Matcher tag = TAG.matcher(text);
        while (tag.find()) {
            if (!tag.group(1).isEmpty()) {
                continue;
            }
            Matcher a = ATTRIBUTE.matcher(text).region(tag.start(3), tag.end(3));
            while (a.find()) {
                spans.add(new Span(a.start(), a.end()));
            }
        }
        return spans;
    }

    /** Where each start tag's name ends: an attribute can be inserted there. */
    static List<Integer> startTagNameEnds(String text) {
        List<Integer> ends = new ArrayList<>();
        Matcher tag = TAG.matcher(text);
        while (tag.find()) {
            if (tag.group(1).isEmpty()) {
                ends.add(tag.end(2));
            }
        }
        return ends;
    }

    /** Every decimal number written in the text. */
    static List<Span> numbers(String text) {
        List<Span> spans = new ArrayList<>();
        Matcher m = NUMBER.matcher(text);
        while (m.find()) {
            spans.add(new Span(m.start(), m.end()));
        }
        return spans;
    }

    /** Every line, with its line end. */
    static List<Span> lines(String text) {
        List<Span> spans = new ArrayList<>();
        int start = 0;
        while (start < text.length()) {
            int end = text.indexOf('\n', start);
            end = end < 0 ? text.length() : end + 1;
            spans.add(new Span(start, end));
            start = end;
        }
        return spans;
    }
}
