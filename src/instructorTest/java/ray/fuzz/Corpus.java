package ray.fuzz;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import ray.scene.SceneFiles;

/**
 * The files the fuzzer starts from: the shipped scenes (every *.xml under a folder, reference
 * renders excluded) and the OBJ meshes and texture images they name. Each worker mutates its own copy of the folder,
 * so the originals are never touched and workers never see each other's damage.
 */
final class Corpus {
    private static final Pattern DATA = Pattern.compile("<data>\\s*([^<]+?)\\s*</data>");
    /** An {@code <image>} holds a texture's path or the scene's size; only an existing file is a texture. */
    private static final Pattern IMAGE = Pattern.compile("<image>\\s*([^<]+?)\\s*</image>");

    private final Path root;
    /** Scene files, relative to the root, sorted. */
    final List<Path> scenes;
    /** Per scene, the meshes it names (relative to the root). */
    final Map<Path, List<Path>> meshes;
    /** Per scene, the texture images it names (relative to the root). */
    final Map<Path, List<Path>> textures;
    /** The bytes of every scene, mesh and texture, read once: each case starts from them. */
    private final Map<Path, byte[]> originals = new HashMap<>();

    private Corpus(Path root, List<Path> scenes, Map<Path, List<Path>> meshes, Map<Path, List<Path>> textures) {
        this.root = root;
        this.scenes = scenes;
        this.meshes = meshes;
        this.textures = textures;
        for (Path scene : scenes) {
            originals.put(scene, readBytes(root.resolve(scene)));
            for (Path file : meshes.get(scene)) {
                originals.computeIfAbsent(file, m -> readBytes(root.resolve(m)));
            }
            for (Path file : textures.get(scene)) {
                originals.computeIfAbsent(file, m -> readBytes(root.resolve(m)));
            }
        }
    }

    static Corpus of(Path root) {
        List<Path> scenes = SceneFiles.under(root, root.resolve("reference")).stream().map(root::relativize)
                .collect(Collectors.toList());
        if (scenes.isEmpty()) {
            throw new IllegalArgumentException("no scene files under " + root);
        }
        Map<Path, List<Path>> meshes = new LinkedHashMap<>();
        Map<Path, List<Path>> textures = new LinkedHashMap<>();
        for (Path scene : scenes) {
            String text = read(root.resolve(scene));
            meshes.put(scene, filesNamed(root, scene, DATA.matcher(text)));
            textures.put(scene, filesNamed(root, scene, IMAGE.matcher(text)));
        }
        return new Corpus(root, Collections.unmodifiableList(scenes), meshes, textures);
    }

    /** The existing files that the matches name, relative to the root, each once, in the scene's order. */
    private static List<Path> filesNamed(Path root, Path scene, Matcher m) {
        List<Path> named = new ArrayList<>();
        while (m.find()) {
            Path file = root.relativize(root.resolve(scene).getParent().resolve(m.group(1)).normalize());
            if (Files.isRegularFile(root.resolve(file)) && !named.contains(file)) {
                named.add(file);
            }
        }
        return Collections.unmodifiableList(named);
    }

    /** The original bytes of a scene, mesh or texture of the corpus (a copy: the caller may change it). */
    byte[] original(Path relative) {
        return originals.get(relative).clone();
    }

    private static byte[] readBytes(Path file) {
        try {
            return Files.readAllBytes(file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Copies the scenes and meshes (not the reference renders) into {@code folder}, for one worker to damage. */
    void copyTo(Path folder) {
        try (Stream<Path> files = Files.walk(root)) {
            for (Path file : (Iterable<Path>) files::iterator) {
                Path relative = root.relativize(file);
                if (!Files.isRegularFile(file) || relative.startsWith("reference")) {
                    continue;
                }
                Path copy = folder.resolve(relative.toString());
                Files.createDirectories(copy.getParent());
                Files.copy(file, copy);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static String read(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
