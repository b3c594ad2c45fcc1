package ray.fuzz;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;

/**
 * One fuzz case, a pure function of the seed and its index: which scene is loaded, which file of it
 * (the scene or one of its meshes or textures) is damaged, and by which mutations, applied in order. The same
 * seed and index give the same case on any machine and with any number of workers.
 */
final class FuzzCase {
    final long index;
    final Path scene;
    /** The damaged file: the scene itself or one of its meshes or textures. */
    final Path target;
    final FileKind kind;
    final List<Mutation> mutations;
    /** The random numbers the mutations draw, seeded per case. */
    final long mutationSeed;

    private FuzzCase(long index, Path scene, Path target, FileKind kind, List<Mutation> mutations, long mutationSeed) {
        this.index = index;
        this.scene = scene;
        this.target = target;
        this.kind = kind;
        this.mutations = mutations;
        this.mutationSeed = mutationSeed;
    }

    static FuzzCase of(Corpus corpus, long seed, long index) {
        Random random = new Random(mix(seed, index));
        Path scene = corpus.scenes.get(random.nextInt(corpus.scenes.size()));
        List<Path> meshes = corpus.meshes.get(scene);
        List<Path> files = new ArrayList<>(meshes);
        files.addAll(corpus.textures.get(scene));
        // A third of the cases of a scene with meshes or textures damage one of them: they are most of the bytes it reads.
        boolean damageFile = !files.isEmpty() && random.nextInt(3) == 0;
        Path target = damageFile ? files.get(random.nextInt(files.size())) : scene;
        FileKind kind = !damageFile ? FileKind.SCENE : meshes.contains(target) ? FileKind.MESH : FileKind.TEXTURE;
        List<Mutation> kinds = new ArrayList<>();
        for (Mutation m : Mutation.values()) {
            if (m.appliesTo(kind)) {
                kinds.add(m);
            }
        }
        // Mostly one mutation, so that each figure is the effect of one kind; sometimes two or three stacked.
        int r = random.nextInt(10);
        int count = r < 7 ? 1 : r < 9 ? 2 : 3;
        List<Mutation> mutations = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            mutations.add(kinds.get(random.nextInt(kinds.size())));
        }
        return new FuzzCase(index, scene, target, kind, Collections.unmodifiableList(mutations), random.nextLong());
    }

    /** The damaged bytes of the target. */
    byte[] damage(byte[] original) {
        Random random = new Random(mutationSeed);
        byte[] bytes = original;
        for (Mutation m : mutations) {
            bytes = m.apply(bytes, random);
        }
        return bytes;
    }

    /** The seed's and index's bits mixed (SplitMix64's finalizer), so that neighbouring indices give unrelated cases. */
    private static long mix(long seed, long index) {
        long z = seed * 0x9E3779B97F4A7C15L + index;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    @Override
    public String toString() {
        return "case " + index + ": " + mutations + " of " + target + (kind == FileKind.SCENE ? "" : " (" + kind.label + " of " + scene + ")");
    }
}
