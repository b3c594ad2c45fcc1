package ray.math;

/**
 * The check of a property that must be a positive finite number (a radius, a height, a view's
 * width, a refractive index), in the words the scene loader puts on the property's line:
 * "radius is -1.0; expected a positive number".
 */
public final class PositiveNumber {
    private PositiveNumber() {
    }

    /**
     * {@code value}, if it is positive and finite.
     *
     * @throws IllegalArgumentException otherwise, naming the property {@code name}
     */
    public static double require(String name, double value) {
        if (!(value > 0) || Double.isInfinite(value)) {
            throw new IllegalArgumentException(name + " is " + value + "; expected a positive number");
        }
        return value;
    }
}
