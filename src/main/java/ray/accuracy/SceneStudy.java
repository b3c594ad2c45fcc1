package ray.accuracy;

import java.util.ArrayList;
import java.util.List;
import ray.image.Image;
import ray.render.PixelWindow;

/** The accuracy study of one scene: the window it measured, its reference, and every run by sweep. */
public final class SceneStudy {
    public final String name;
    public final int width;
    public final int height;
    public final double exposure;
    /** The scene's own samples per pixel (the choice sweeps render with these). */
    public final int sceneSamples;
    public final PixelWindow window;
    public final int referenceSamples;
    public final double referenceSeconds;
    public final Image reference;
    public final List<Sweep> sweeps;
    /** Sweeps of the full study that this copy does not have (see {@link Sweeps#missing}). */
    public final List<String> missing;
    public final List<Run> runs;

    SceneStudy(String name, int width, int height, double exposure, int sceneSamples, PixelWindow window,
            int referenceSamples, double referenceSeconds, Image reference, List<Sweep> sweeps, List<String> missing,
            List<Run> runs) {
        this.name = name;
        this.width = width;
        this.height = height;
        this.exposure = exposure;
        this.sceneSamples = sceneSamples;
        this.window = window;
        this.referenceSamples = referenceSamples;
        this.referenceSeconds = referenceSeconds;
        this.reference = reference;
        this.sweeps = List.copyOf(sweeps);
        this.missing = List.copyOf(missing);
        this.runs = List.copyOf(runs);
    }

    /** The runs of one sweep, in its order. */
    public List<Run> runs(String sweep) {
        List<Run> list = new ArrayList<>();
        for (Run run : runs) {
            if (run.sweep.equals(sweep)) {
                list.add(run);
            }
        }
        return list;
    }

    /** The run with this label, or null. */
    public Run run(String label) {
        for (Run run : runs) {
            if (run.setting.label.equals(label)) {
                return run;
            }
        }
        return null;
    }
}
