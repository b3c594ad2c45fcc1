package ray.cli;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.concurrent.Callable;
import javax.imageio.ImageIO;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import ray.image.ImageDiff;
import ray.image.PngWriter;

/**
 * {@code ray1 diff}: compares two PNGs as the graded render tests do ({@link ImageDiff}).
 * Exit status 0 when they match within the tolerance, 1 when they do not (different sizes
 * included), 2 when they cannot be compared (a missing or unreadable file, not a PNG, bad usage).
 */
@Command(name = "diff", mixinStandardHelpOptions = true,
        description = {"Compares two PNG images as the render tests do: PASS when the share of pixels that differ by more than "
                + ImageDiff.TOLERANCE_LEVELS + " levels (of 255) in some channel is at most " + ImageDiff.MAX_SHARE + ".",
            "Exit status: 0 PASS, 1 FAIL (also for different sizes), 2 when the files cannot be compared."})
public final class DiffCommand implements Callable<Integer> {
    /** Exit status when a file is missing, unreadable or not a PNG. */
    static final int CANNOT_COMPARE = 2;
    private static final byte[] PNG_SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

    @Parameters(index = "0", paramLabel = "EXPECTED.png", description = "The reference image, e.g. scenes/reference/one-sphere.png.")
    Path expected;

    @Parameters(index = "1", paramLabel = "ACTUAL.png", description = "The image to check, e.g. out/one-sphere.png.")
    Path actual;

    @Option(names = {"-o", "--output"}, paramLabel = "DIFF.png",
            description = "Also write a heat map: black where equal, blue within the tolerance, red to yellow to white beyond it.")
    Path heatMap;

    @CommandLine.Mixin
    Verbosity verbosity;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        BufferedImage a;
        BufferedImage b;
        try {
            a = readPng(expected);
            b = readPng(actual);
        } catch (IOException e) {
            err.println("error: " + e.getMessage());
            return CANNOT_COMPARE;
        }
        ImageDiff.Result result = ImageDiff.compare(a, b);
        if (!result.sameSize()) {
            out.println("FAIL: the images differ in size: " + expected + " is " + a.getWidth() + "x" + a.getHeight() + ", "
                    + actual + " is " + b.getWidth() + "x" + b.getHeight() + (heatMap != null ? " (no heat map written)" : ""));
            return 1;
        }
        out.println(result);
        if (heatMap != null) {
            try {
                PngWriter.write(result.heatMap(), heatMap);
            } catch (IOException e) {
                err.println("error: cannot write the heat map " + heatMap + ": " + e.getMessage());
                return CANNOT_COMPARE;
            }
            out.println("heat map: " + heatMap);
        }
        return result.passed() ? 0 : 1;
    }

    /** The file as an image, or an IOException whose message is one line naming the file and the problem. */
    private static BufferedImage readPng(Path file) throws IOException {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            throw new IOException(file + ": no such file");
        } catch (IOException e) {
            throw new IOException(file + ": cannot read it (" + (Files.isDirectory(file) ? "it is a folder" : e.getMessage()) + ")");
        }
        if (bytes.length < PNG_SIGNATURE.length || !Arrays.equals(bytes, 0, PNG_SIGNATURE.length, PNG_SIGNATURE, 0, PNG_SIGNATURE.length)) {
            throw new IOException(file + " is not a PNG file");
        }
        BufferedImage image;
        try {
            image = ImageIO.read(new ByteArrayInputStream(bytes));
        } catch (IOException | RuntimeException e) {
            throw new IOException(file + " is a damaged PNG file (" + e.getMessage() + ")");
        }
        if (image == null) {
            throw new IOException(file + " is a damaged PNG file");
        }
        return image;
    }
}
