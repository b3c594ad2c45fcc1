package ray.accuracy;

import java.util.List;
import java.util.function.Predicate;
import ray.scene.Scene;

/**
 * One axis of the accuracy study: the settings that differ in one choice only. The first setting
 * of a choice sweep is its baseline, the framework's own choice; the samples sweep has none (every
 * point is measured against the converged reference).
 */
public final class Sweep {
    /** "samples", "arithmetic", "intersection", "fresnel", "masking", "offsets", "depth" or "acceleration". */
    public final String name;
    /** What is being compared, one sentence for the report. */
    public final String question;
    public final List<Setting> settings;
    /** Whether the first setting is the baseline that the others' defects are counted against. */
    public final boolean hasBaseline;
    /** The scenes the sweep measures: those whose settings can differ (the microfacet sweeps: scenes with a microfacet shader). */
    private final Predicate<Scene> appliesTo;

    public Sweep(String name, String question, List<Setting> settings, boolean hasBaseline) {
        this(name, question, settings, hasBaseline, scene -> true);
    }

    /** A sweep measured only on the scenes {@code appliesTo} accepts. */
    public Sweep(String name, String question, List<Setting> settings, boolean hasBaseline, Predicate<Scene> appliesTo) {
        if (settings.isEmpty()) {
            throw new IllegalArgumentException("the sweep " + name + " has no settings");
        }
        this.name = name;
        this.question = question;
        this.settings = List.copyOf(settings);
        this.hasBaseline = hasBaseline;
        this.appliesTo = appliesTo;
    }

    /** Whether the sweep measures {@code scene}. */
    public boolean appliesTo(Scene scene) {
        return appliesTo.test(scene);
    }

    public Setting baseline() {
        return settings.get(0);
    }
}
