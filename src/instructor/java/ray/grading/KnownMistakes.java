package ray.grading;

import java.awt.image.BufferedImage;
import java.util.List;
import java.util.function.UnaryOperator;
import ray.image.ImageDiff;

/**
 * Names the mistake behind a wrong render when the render is the reference changed in a known way:
 * the reference flipped upside down (v measured from the top of the image), or mirrored left to
 * right (u from the right, or the camera's u = w × up instead of up × w). Each is recognized by the
 * render tests' own comparison ({@link ImageDiff}), so a correct render, which matches the reference
 * itself, never gets a name.
 */
public final class KnownMistakes {
    /** A mistake that shows as the reference changed by {@code change}, with what to tell the student. */
    private static final class Mistake {
        final UnaryOperator<BufferedImage> change;
        final String advice;

        Mistake(UnaryOperator<BufferedImage> change, String advice) {
            this.change = change;
            this.advice = advice;
        }
    }

    /** How every piece of this advice begins. */
    static final String ADVICE_START = "Your image matches the reference ";

    private static final List<Mistake> MISTAKES = List.of(
            new Mistake(KnownMistakes::flippedVertically, ADVICE_START + "flipped upside down: the image point's"
                    + " imageV is measured from the bottom of the image (imageV = 0 is the bottom row), and"
                    + " planeV = (imageV − ½)·viewHeight runs along the basis vector v, which points up (see TODO(Task 1), step 1)."),
            new Mistake(KnownMistakes::flippedHorizontally, ADVICE_START + "mirrored left to right: imageU grows to"
                    + " the right, and the camera's u is normalize(viewUp × w), not w × viewUp (see TODO(Task 1), step 1)."));

    private KnownMistakes() {
    }

    /** What the student's render shows, when it is the reference changed by a known mistake; else null. */
    static String of(BufferedImage yours, BufferedImage reference) {
        if (ImageDiff.compare(reference, yours).passed()) {
            return null;
        }
        for (Mistake m : MISTAKES) {
            BufferedImage changed = m.change.apply(reference);
            if (changed.getWidth() == yours.getWidth() && changed.getHeight() == yours.getHeight()
                    && ImageDiff.compare(changed, yours).passed()) {
                return m.advice;
            }
        }
        return null;
    }

    /** The image upside down (also a defect the render tests' tolerance survey must catch). */
    public static BufferedImage flippedVertically(BufferedImage image) {
        BufferedImage out = new BufferedImage(image.getWidth(), image.getHeight(), BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                out.setRGB(x, image.getHeight() - 1 - y, image.getRGB(x, y));
            }
        }
        return out;
    }

    static BufferedImage flippedHorizontally(BufferedImage image) {
        BufferedImage out = new BufferedImage(image.getWidth(), image.getHeight(), BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                out.setRGB(image.getWidth() - 1 - x, y, image.getRGB(x, y));
            }
        }
        return out;
    }
}
