package ray.accuracy;

import java.util.List;

/**
 * More sweeps for the accuracy study, found with {@link java.util.ServiceLoader}. The instructor's
 * copy provides the arithmetic (float vs double) and intersection (textbook vs robust) sweeps this
 * way: their code is the assignment's answers, so it never ships, and a student's copy runs the
 * sweeps it has.
 */
public interface SweepProvider {
    List<Sweep> sweeps();
}
