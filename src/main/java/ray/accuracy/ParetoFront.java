package ray.accuracy;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.ToDoubleFunction;

/**
 * The choices worth their price: of a set of runs, each with a cost (time) and an error, those
 * that no other run beats on both, i.e. no other run is at most as slow and at most as wrong and
 * better in one of the two.
 */
public final class ParetoFront {
    private ParetoFront() {
    }

    /** The non-dominated items, by increasing cost (and so decreasing error). */
    public static <T> List<T> of(List<T> items, ToDoubleFunction<T> cost, ToDoubleFunction<T> error) {
        List<T> sorted = new ArrayList<>(items);
        // By cost, ties by error: then an item is on the front exactly when its error is below
        // every error before it.
        sorted.sort(Comparator.comparingDouble(cost).thenComparingDouble(error));
        List<T> front = new ArrayList<>();
        double best = Double.POSITIVE_INFINITY;
        for (T item : sorted) {
            double e = error.applyAsDouble(item);
            if (e < best) {
                front.add(item);
                best = e;
            }
        }
        return front;
    }
}
