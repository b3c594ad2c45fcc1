package ray.assignment;

import java.util.Locale;

/**
 * How much a task's TODO comments and failure messages say. Every level states the method's
 * contract and the conventions a reference image depends on (which way u, v and rows run, the
 * sphere's texture coordinates, open segments), since a correct solution with another convention
 * would lose points; beyond that:
 */
public enum HintLevel {
    /** The goal alone: what the method must do. Failure messages say what was expected and what came back, never the fix. */
    GOAL,
    /** What to compute, step by step, in words, without formulas. */
    STEPS,
    /** The steps with their formulas, nearly line by line. */
    FORMULAS;

    /** "goal", as assignment files and the hint markers of the TODO comments name it. */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The level named {@code id}, or null. */
    public static HintLevel of(String id) {
        for (HintLevel level : values()) {
            if (level.id().equals(id.trim())) {
                return level;
            }
        }
        return null;
    }
}
