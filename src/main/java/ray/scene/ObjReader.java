package ray.scene;

import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CoderResult;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.stream.DoubleStream;
import java.util.stream.IntStream;
import ray.surface.MeshData;

/**
 * Reads the geometry of a Wavefront OBJ file: {@code v}, {@code vn}, {@code vt} and {@code f} in
 * every index form ({@code 1}, {@code 1/2}, {@code 1//3}, {@code 1/2/3}, negative indices counting
 * back from the latest vertex). Polygons are split into fans around their first vertex. Grouping,
 * smoothing and material statements ({@code o g s usemtl mtllib}) and comments are ignored.
 * The file is UTF-8 text (a byte order mark is skipped); its comments may hold any bytes.
 * Errors name the OBJ file and its own line number.
 */
public final class ObjReader {
    private static final String KIND = "an OBJ file";
    /** The UTF-8 byte order mark, EF BB BF, as Latin-1 characters. */
    private static final String UTF8_BYTE_ORDER_MARK = "\u00EF\u00BB\u00BF";
    private final Path file;
    // Primitive builders, so that a large mesh does not box a value per coordinate.
    private final DoubleStream.Builder positions = DoubleStream.builder();
    private final DoubleStream.Builder normals = DoubleStream.builder();
    private final IntStream.Builder triangles = IntStream.builder();
    private final IntStream.Builder triangleNormals = IntStream.builder();
    private final DoubleStream.Builder texCoords = DoubleStream.builder();
    private final IntStream.Builder triangleTexCoords = IntStream.builder();
    private int vertexCount;
    private int normalCount;
    private int texCoordCount;
    private int triangleCount;
    private boolean anyNormals;
    private boolean anyTexCoords;
    private int lineNumber;
    private final int maxVertices;
    private final int maxTriangles;

    private ObjReader(Path file, int maxVertices, int maxTriangles) {
        this.file = file;
        this.maxVertices = maxVertices;
        this.maxTriangles = maxTriangles;
    }

    /** Reads a mesh of at most {@link Limits#MAX_MESH_VERTICES} vertices and {@link Limits#MAX_MESH_TRIANGLES} triangles. */
    public static MeshData read(Path file) {
        return read(file, Limits.MAX_MESH_VERTICES, Limits.MAX_MESH_TRIANGLES);
    }

    /** With other limits, so that a test can reach them with a small file. */
    static MeshData read(Path file, int maxVertices, int maxTriangles) {
        return new ObjReader(file, maxVertices, maxTriangles).readAll();
    }

    private MeshData readAll() {
        FileProblems.checkIsFile(file, KIND);
        // Read byte for byte (every byte is a Latin-1 character), so that no byte can stop the reading
        // with a decoder's exception; statement() then checks that each statement is UTF-8 text.
        // BoundedLines buffers the text itself, so no BufferedReader is needed.
        try (Reader in = new InputStreamReader(Files.newInputStream(file), StandardCharsets.ISO_8859_1)) {
            BoundedLines lines = new BoundedLines(in, Limits.MAX_OBJ_LINE);
            String line;
            while ((line = lines.next()) != null) {
                lineNumber++;
                parseLine(statement(line));
            }
        } catch (BoundedLines.TooLong e) {
            throw new SceneException(file, lineNumber + 1, 1, "the line is longer than " + Limits.MAX_OBJ_LINE
                    + " characters; expected an OBJ statement (v, vn, vt, f, ...) per line");
        } catch (IOException e) {
            throw FileProblems.cannotRead(file, e, KIND);
        }
        if (lineNumber == 0) {
            throw new SceneException(file, 1, 1, "the mesh file is empty; expected 'v' and 'f' lines");
        }
        if (triangleCount == 0) {
            throw error("the mesh has no faces; expected at least one 'f' line");
        }
        return new MeshData(file, positions.build().toArray(), normals.build().toArray(), triangles.build().toArray(),
                anyNormals ? triangleNormals.build().toArray() : null, texCoords.build().toArray(),
                anyTexCoords ? triangleTexCoords.build().toArray() : null);
    }

    /**
     * The statement on a line read as Latin-1 bytes: without its comment (a '#' byte, which is never
     * part of a longer UTF-8 character) and decoded as UTF-8. A comment may hold any bytes; a
     * statement that is not UTF-8 text is an error.
     */
    private String statement(String latin1) {
        int hash = latin1.indexOf('#');
        String s = hash >= 0 ? latin1.substring(0, hash) : latin1;
        if (lineNumber == 1 && s.startsWith(UTF8_BYTE_ORDER_MARK)) {
            s = s.substring(UTF8_BYTE_ORDER_MARK.length());
        }
        boolean ascii = s.chars().allMatch(c -> c < 0x80);
        if (ascii) {
            return s;
        }
        ByteBuffer bytes = ByteBuffer.wrap(s.getBytes(StandardCharsets.ISO_8859_1));
        CharBuffer chars = CharBuffer.allocate(bytes.remaining());
        CoderResult result = StandardCharsets.UTF_8.newDecoder().decode(bytes, chars, true);
        if (result.isError()) {
            int bad = bytes.get(bytes.position()) & 0xFF;
            throw error(String.format(Locale.ROOT, "byte 0x%02X is not UTF-8 text; expected OBJ text in UTF-8 (or ASCII)", bad));
        }
        return chars.flip().toString();
    }

    private void parseLine(String statement) {
        String line = statement.strip();
        if (line.isEmpty()) {
            return;
        }
        String[] words = line.split("\\s+");
        switch (words[0]) {
            case "v":
                checkCount(vertexCount, maxVertices, "vertices");
                readVector(words, positions, "v x y z");
                vertexCount++;
                break;
            case "vn":
                checkCount(normalCount, maxVertices, "normals");
                readVector(words, normals, "vn x y z");
                normalCount++;
                break;
            case "vt":
                if (words.length < 2) {
                    throw error("'vt' has no coordinates; expected vt u [v [w]]");
                }
                checkCount(texCoordCount, maxVertices, "texture coordinates");
                // v defaults to 0 (the format allows "vt u"); w, for 3D textures, is not used.
                texCoords.add(parseNumber(words[1], "vt u [v [w]]"));
                texCoords.add(words.length > 2 ? parseNumber(words[2], "vt u [v [w]]") : 0);
                if (words.length > 3) {
                    parseNumber(words[3], "vt u [v [w]]");
                }
                texCoordCount++;
                break;
            case "f":
                readFace(words);
                break;
            default:
                // o, g, s, usemtl, mtllib and other statements carry nothing the renderer uses.
                break;
        }
    }

    private void readVector(String[] words, DoubleStream.Builder into, String form) {
        // "v x y z w" is allowed by the format (w is a weight we ignore); so are vertex colors after xyz.
        if (words.length < 4) {
            int n = words.length - 1;
            throw error("'" + words[0] + "' has " + (n == 0 ? "no numbers" : n == 1 ? "1 number" : n + " numbers")
                    + "; expected " + form);
        }
        for (int i = 1; i <= 3; i++) {
            into.add(parseNumber(words[i], form));
        }
    }

    private double parseNumber(String word, String form) {
        double value;
        try {
            value = Double.parseDouble(word);
        } catch (NumberFormatException e) {
            throw error("\"" + SceneException.excerpt(word) + "\" is not a number; expected " + form);
        }
        if (!Double.isFinite(value)) {
            throw error("\"" + SceneException.excerpt(word) + "\" is not a finite number; expected " + form);
        }
        return value;
    }

    private void readFace(String[] words) {
        int corners = words.length - 1;
        if (corners < 3) {
            throw error("the face has " + (corners == 0 ? "no vertices" : corners == 1 ? "1 vertex" : corners + " vertices")
                    + "; expected at least 3: f v1 v2 v3 ...");
        }
        int[] vertex = new int[corners];
        int[] normal = new int[corners];
        int[] texCoord = new int[corners];
        boolean faceHasNormals = true;
        boolean faceHasTexCoords = true;
        for (int i = 0; i < corners; i++) {
            String[] parts = words[i + 1].split("/", -1);
            if (parts.length > 3 || parts[0].isEmpty()) {
                throw error("\"" + SceneException.excerpt(words[i + 1])
                        + "\" is not a face vertex; expected v, v/vt, v//vn or v/vt/vn");
            }
            vertex[i] = index(parts[0], vertexCount, "vertex");
            if (parts.length >= 2 && !parts[1].isEmpty()) {
                texCoord[i] = index(parts[1], texCoordCount, "texture coordinate");
            } else {
                faceHasTexCoords = false;
            }
            if (parts.length == 3 && !parts[2].isEmpty()) {
                normal[i] = index(parts[2], normalCount, "normal");
            } else {
                faceHasNormals = false;
            }
        }
        anyNormals |= faceHasNormals;
        anyTexCoords |= faceHasTexCoords;
        for (int k = 1; k + 1 < corners; k++) {
            checkCount(triangleCount, maxTriangles, "triangles");
            triangleCount++;
            triangles.add(vertex[0]);
            triangles.add(vertex[k]);
            triangles.add(vertex[k + 1]);
            // -1 marks a corner without a normal: that triangle is flat-shaded.
            triangleNormals.add(faceHasNormals ? normal[0] : -1);
            triangleNormals.add(faceHasNormals ? normal[k] : -1);
            triangleNormals.add(faceHasNormals ? normal[k + 1] : -1);
            // Likewise -1 for a corner without texture coordinates: that triangle has (0, 0) everywhere.
            triangleTexCoords.add(faceHasTexCoords ? texCoord[0] : -1);
            triangleTexCoords.add(faceHasTexCoords ? texCoord[k] : -1);
            triangleTexCoords.add(faceHasTexCoords ? texCoord[k + 1] : -1);
        }
    }

    /** Stops a mesh that is about to pass one of the {@link Limits}, at the line that passes it. */
    private void checkCount(int count, int limit, String what) {
        if (count == limit) {
            throw error("the mesh has more than " + limit + " " + what + "; expected at most " + limit);
        }
    }

    /** A 1-based (or negative, relative) OBJ index as a 0-based index, checked against the {@code count} defined so far. */
    private int index(String word, int count, String what) {
        int i;
        try {
            i = Integer.parseInt(word);
        } catch (NumberFormatException e) {
            throw error("\"" + SceneException.excerpt(word) + "\" is not a " + what + " index; expected an integer");
        }
        int zeroBased = i > 0 ? i - 1 : count + i;
        if (i == 0 || zeroBased < 0 || zeroBased >= count) {
            if (count == 0) {
                throw error(what + " index " + i + " is out of range; expected a " + what + " defined on an earlier line"
                        + " (none is defined so far)");
            }
            throw error(what + " index " + i + " is out of range; expected 1 to " + count + " or -1 to -" + count
                    + " (" + count + " defined so far)");
        }
        return zeroBased;
    }

    private SceneException error(String problem) {
        return new SceneException(file, Math.max(1, lineNumber), 1, problem);
    }
}
