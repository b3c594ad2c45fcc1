package ray.fuzz;

import java.nio.charset.StandardCharsets;
import java.util.EnumSet;
import java.util.List;
import java.util.Random;
import java.util.Set;

/**
 * The ways the fuzzer damages a file. Byte flips model a corrupted or mistyped file; deletions and
 * duplications model the edits a student makes by copy and paste; number mutations reach the values
 * where geometry and memory break (zero, negative, huge, tiny, past the limits). Each mutation
 * returns the text unchanged when it finds nothing to act on (e.g. no attribute left).
 */
enum Mutation {
    /** One to four bytes: a bit flipped, a byte replaced by any byte, inserted or removed. */
    BYTE_FLIP(FileKind.SCENE, FileKind.MESH, FileKind.TEXTURE),
    /** A whole element, with everything inside it, removed. */
    ELEMENT_DELETE(FileKind.SCENE),
    /** A whole element written twice in a row. */
    ELEMENT_DUPLICATE(FileKind.SCENE),
    /** An attribute (type, name or ref) removed. */
    ATTRIBUTE_DELETE(FileKind.SCENE),
    /** An attribute written a second time, in its own tag (not XML) or in another start tag. */
    ATTRIBUTE_DUPLICATE(FileKind.SCENE),
    /** A number replaced by a value from {@link #NUMBERS}, negated, scaled by a power of ten, or given an extra digit. */
    NUMBER(FileKind.SCENE, FileKind.MESH),
    /** A line of an OBJ file removed: a vertex that faces still count on, or a face. */
    LINE_DELETE(FileKind.MESH),
    /** A line of an OBJ file written twice: one vertex more shifts no index, one face more is a duplicate. */
    LINE_DUPLICATE(FileKind.MESH);

    /** Values where arithmetic, geometry or the limits change behaviour. */
    static final List<String> NUMBERS = List.of("0", "-0", "-1", "1", "0.5", "1e-9", "1e-300", "4.9e-324", "1e300",
            "-1e300", "1.7976931348623157e308", "1e309", "2147483647", "2147483648", "-2147483648", "99999999999",
            "8192", "8193", "4096", "65536", "65537", "1e6", "3.", ".5", "007", "1e", "--1", "NaN", "Infinity", "");

    /** The kinds of file it applies to: scene files (XML), mesh files (OBJ), texture images (bytes only). */
    private final Set<FileKind> kinds;

    Mutation(FileKind first, FileKind... more) {
        this.kinds = EnumSet.of(first, more);
    }

    boolean appliesTo(FileKind kind) {
        return kinds.contains(kind);
    }

    /** Applies the mutation to a file's bytes; the text mutations read and write UTF-8. */
    byte[] apply(byte[] bytes, Random random) {
        if (this == BYTE_FLIP) {
            return flipBytes(bytes, random);
        }
        return apply(new String(bytes, StandardCharsets.UTF_8), random).getBytes(StandardCharsets.UTF_8);
    }

    /**
     * Applies a text mutation. (A switch rather than a method body per constant: an enum with
     * bodies compiles to a sealed class, which Gradle 4.4's class scanner cannot read.)
     */
    String apply(String text, Random random) {
        switch (this) {
            case ELEMENT_DELETE:
                return deleteElement(text, random);
            case ELEMENT_DUPLICATE:
                return duplicateElement(text, random);
            case ATTRIBUTE_DELETE:
                return deleteAttribute(text, random);
            case ATTRIBUTE_DUPLICATE:
                return duplicateAttribute(text, random);
            case NUMBER:
                return mutateNumber(text, random);
            case LINE_DELETE:
                return deleteLine(text, random);
            case LINE_DUPLICATE:
                return duplicateLine(text, random);
            default:
                throw new UnsupportedOperationException(name() + " works on bytes");
        }
    }

    private static byte[] flipBytes(byte[] bytes, Random random) {
        byte[] b = bytes.clone();
        for (int n = 1 + random.nextInt(4); n > 0 && b.length > 0; n--) {
            int at = random.nextInt(b.length);
            switch (random.nextInt(4)) {
                case 0:
                    b[at] ^= (byte) (1 << random.nextInt(8));
                    break;
                case 1:
                    b[at] = (byte) random.nextInt(256);
                    break;
                case 2:
                    b = splice(b, at, at, new byte[] {(byte) random.nextInt(256)});
                    break;
                default:
                    b = splice(b, at, at + 1, new byte[0]);
                    break;
            }
        }
        return b;
    }

    private static String deleteElement(String text, Random random) {
        return replace(text, pick(Markup.elements(text), random), "");
    }

    private static String duplicateElement(String text, Random random) {
        Markup.Span s = pick(Markup.elements(text), random);
        return s == null ? text : text.substring(0, s.end) + text.substring(s.start, s.end) + text.substring(s.end);
    }

    private static String deleteAttribute(String text, Random random) {
        return replace(text, pick(Markup.attributes(text), random), "");
    }

    private static String duplicateAttribute(String text, Random random) {
        Markup.Span a = pick(Markup.attributes(text), random);
        if (a == null) {
            return text;
        }
        String attribute = text.substring(a.start, a.end);
        if (random.nextBoolean()) {
            return text.substring(0, a.end) + attribute + text.substring(a.end);
        }
        List<Integer> tags = Markup.startTagNameEnds(text);
        int at = tags.get(random.nextInt(tags.size()));
        return text.substring(0, at) + attribute + text.substring(at);
    }

    private static String mutateNumber(String text, Random random) {
        Markup.Span s = pick(Markup.numbers(text), random);
        if (s == null) {
            return text;
        }
        String number = text.substring(s.start, s.end);
        String replacement;
        switch (random.nextInt(4)) {
            case 0:
                replacement = number.startsWith("-") ? number.substring(1) : "-" + number;
                break;
            case 1:
                replacement = number + "e" + (random.nextInt(49) - 24);
                break;
            case 2:
                replacement = number + random.nextInt(10);
                break;
            default:
                replacement = NUMBERS.get(random.nextInt(NUMBERS.size()));
                break;
        }
        return replace(text, s, replacement);
    }

    private static String deleteLine(String text, Random random) {
        return replace(text, pick(Markup.lines(text), random), "");
    }

    private static String duplicateLine(String text, Random random) {
        Markup.Span s = pick(Markup.lines(text), random);
        return s == null ? text : text.substring(0, s.end) + text.substring(s.start, s.end) + text.substring(s.end);
    }

    private static <T> T pick(List<T> items, Random random) {
        return items.isEmpty() ? null : items.get(random.nextInt(items.size()));
    }

    private static String replace(String text, Markup.Span s, String replacement) {
        return s == null ? text : text.substring(0, s.start) + replacement + text.substring(s.end);
    }

    private static byte[] splice(byte[] b, int from, int to, byte[] insert) {
        byte[] out = new byte[b.length - (to - from) + insert.length];
        System.arraycopy(b, 0, out, 0, from);
        System.arraycopy(insert, 0, out, from, insert.length);
        System.arraycopy(b, to, out, from + insert.length, b.length - to);
        return out;
    }
}
