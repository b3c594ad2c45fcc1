package ray.accuracy;

import java.util.List;

/**
 * One axis of the accuracy study: the settings that differ in one choice only. The first setting
 * of a choice sweep is its baseline, the framework's own choice; the samples sweep has none (every
 * point is measured against the converged reference).
 */
public final class Sweep {
    /** "samples", "arithmetic", "intersection" or "offsets". */
    public final String name;
    /** What is being compared, one sentence for the report. */
    public final String question;
    public final List<Setting> settings;
    /** Whether the first setting is the baseline that the others' defects are counted against. */
    public final boolean hasBaseline;

    public Sweep(String name, String question, List<Setting> settings, boolean hasBaseline) {
        if (settings.isEmpty()) {
            throw new IllegalArgumentException("the sweep " + name + " has no settings");
        }
        this.name = name;
        this.question = question;
        this.settings = List.copyOf(settings);
        this.hasBaseline = hasBaseline;
    }

    public Setting baseline() {
        return settings.get(0);
    }
}
