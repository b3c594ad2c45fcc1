package ray.tools;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import javax.imageio.ImageIO;

/**
 * Writes the textures of the textured scenes (scenes/textured), deterministically, each designed so
 * that a mistake in the texture coordinates or the lookup shows plainly in a render:
 * <ul>
 * <li>{@code globe.png} (512×256, latitude–longitude): land and ocean, a grid every 30°, the prime
 *     meridian (u = ½) in yellow, the seam (u = 0 and 1) in magenta, a red north cap and a white
 *     south cap, and an orange mark beside the equator shaped like an "L" turned on its side:
 *     its long arm points east (+u) and its short arm north (+v). A mirrored u turns the arm
 *     west; a flipped v puts the red cap at the bottom; swapped u and v stripe the globe.</li>
 * <li>{@code moon.png} (256×128): gray with craters (darker floors, lighter rims) at seeded random
 *     places.</li>
 * <li>{@code plaid.png} (64×64, tileable): a red and cream tablecloth plaid whose period is the
 *     image, so a repeated lookup shows no seams; an off-by-one wrap shows a stripe at each.</li>
 * <li>{@code flower.png} (64×64): a five-petal flower on green, framed by a one-texel border of a
 *     different color on each side (top red, bottom blue, left yellow, right white), so a flipped
 *     row, a swapped u and v or a clamp to the wrong edge texel shows the wrong color there.</li>
 * <li>{@code ruler.png} (4×4): texels big enough to count on a render. The top row is red and the
 *     bottom row blue (both over the corners), the left column yellow and the right one white, and
 *     the 2 × 2 inside a checker of dark and light green, dark at the top left. Which texel shows
 *     where, and how tall the bands at the image's edges are, tells the course's row rule from one
 *     that is a row off (scenes/textured/diagnostic.xml).</li>
 * </ul>
 *
 * <p>Usage: {@code TextureGenerator [FOLDER]} (default {@code scenes/textures}); run by
 * {@code gradle textures}.
 */
public final class TextureGenerator {
    private TextureGenerator() {
    }

    public static void main(String[] args) throws IOException {
        Path folder = Path.of(args.length > 0 ? args[0] : "scenes/textures");
        Files.createDirectories(folder);
        write(globe(512, 256), folder.resolve("globe.png"));
        write(moon(256, 128), folder.resolve("moon.png"));
        write(plaid(64), folder.resolve("plaid.png"));
        write(flower(64), folder.resolve("flower.png"));
        write(ruler(4), folder.resolve("ruler.png"));
    }

    private static void write(BufferedImage image, Path file) throws IOException {
        if (!ImageIO.write(image, "png", file.toFile())) {
            throw new IOException("no PNG writer for " + file);
        }
        System.out.println("wrote " + file + " (" + image.getWidth() + "x" + image.getHeight() + ")");
    }

    private static int rgb(int r, int g, int b) {
        return (r << 16) | (g << 8) | b;
    }

    // The globe. Texel (column x, row y) of a W×H image is sampled at its center: u = (x + ½)/W and
    // v = 1 − (y + ½)/H (row 0 is the top, the north), so longitude λ = 2π(u − ½) and latitude
    // φ = π(v − ½), matching the sphere's u = ½ + atan2(x, z)/2π and v = ½ + asin(y)/π.
    static BufferedImage globe(int width, int height) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        double lineU = 1.5 / width; // grid lines about 3 texels wide
        double lineV = 1.5 / height;
        for (int y = 0; y < height; y++) {
            double v = 1 - (y + 0.5) / height;
            double latitude = Math.PI * (v - 0.5);
            for (int x = 0; x < width; x++) {
                double u = (x + 0.5) / width;
                double longitude = 2 * Math.PI * (u - 0.5);
                image.setRGB(x, y, globeColor(u, v, longitude, latitude, lineU, lineV));
            }
        }
        return image;
    }

    private static int globeColor(double u, double v, double longitude, double latitude, double lineU, double lineV) {
        double degreesNorth = Math.toDegrees(latitude);
        if (degreesNorth > 75) {
            return rgb(210, 40, 40);
        }
        if (degreesNorth < -75) {
            return rgb(235, 235, 240);
        }
        if (u < 2 * lineU || u > 1 - 2 * lineU) {
            return rgb(220, 40, 220);
        }
        if (Math.abs(u - 0.5) < 2 * lineU) {
            return rgb(245, 210, 40);
        }
        // The mark: a long arm east along the equator's north side, a short arm north at its west end.
        boolean eastArm = u > 0.52 && u < 0.64 && v > 0.52 && v < 0.55;
        boolean northArm = u > 0.52 && u < 0.535 && v > 0.52 && v < 0.64;
        if (eastArm || northArm) {
            return rgb(255, 130, 20);
        }
        double nearestMeridian = Math.abs(u * 12 - Math.rint(u * 12)) / 12;
        double nearestParallel = Math.abs(v * 6 - Math.rint(v * 6)) / 6;
        if (nearestMeridian < lineU || nearestParallel < lineV) {
            return rgb(190, 200, 210);
        }
        // Land where a smooth function of the point on the unit sphere is high: continuous across the seam.
        double px = Math.cos(latitude) * Math.sin(longitude);
        double py = Math.sin(latitude);
        double pz = Math.cos(latitude) * Math.cos(longitude);
        double land = Math.sin(3.1 * px + 1.3) * Math.cos(2.3 * pz - 0.4) + 0.6 * Math.sin(4.7 * py + 2.1 * px)
                + 0.35 * Math.cos(6.1 * pz + 5.3 * py);
        if (land > 0.45) {
            int shade = (int) Math.round(30 * Math.min(1, land - 0.45));
            return rgb(60 + shade, 140 - shade, 60);
        }
        return rgb(30, 70, 150);
    }

    static BufferedImage moon(int width, int height) {
        double[][] gray = new double[height][width];
        for (double[] row : gray) {
            java.util.Arrays.fill(row, 150);
        }
        Random random = new Random(20_190_101);
        for (int crater = 0; crater < 60; crater++) {
            double cx = width * random.nextDouble();
            double cy = height * (0.1 + 0.8 * random.nextDouble());
            double r = 2 + 10 * Math.pow(random.nextDouble(), 2);
            for (int y = 0; y < height; y++) {
                for (int x = 0; x < width; x++) {
                    // Distance across the seam too, so craters at u near 0 or 1 wrap around.
                    double dx = Math.min(Math.abs(x + 0.5 - cx), width - Math.abs(x + 0.5 - cx));
                    double d = Math.hypot(dx, y + 0.5 - cy) / r;
                    if (d < 0.85) {
                        gray[y][x] -= 35;
                    } else if (d < 1.1) {
                        gray[y][x] += 30;
                    }
                }
            }
        }
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int g = (int) Math.max(40, Math.min(230, gray[y][x]));
                image.setRGB(x, y, rgb(g, g, g - 6));
            }
        }
        return image;
    }

    // Plaid: the same band sequence across and down, and each texel the mean of its column's and its
    // row's band, so crossings of two dark bands are darkest. The sequence spans the whole image,
    // so the pattern tiles.
    private static final int[][] PLAID_BANDS = {
        // {first texel, last texel (exclusive), r, g, b}
        {0, 14, 190, 30, 40}, {14, 18, 240, 230, 205}, {18, 22, 60, 30, 40}, {22, 26, 240, 230, 205},
        {26, 40, 190, 30, 40}, {40, 64, 240, 230, 205},
    };

    static BufferedImage plaid(int side) {
        BufferedImage image = new BufferedImage(side, side, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < side; y++) {
            int[] row = plaidBand(y * 64 / side);
            for (int x = 0; x < side; x++) {
                int[] column = plaidBand(x * 64 / side);
                image.setRGB(x, y, rgb((row[2] + column[2]) / 2, (row[3] + column[3]) / 2, (row[4] + column[4]) / 2));
            }
        }
        return image;
    }

    private static int[] plaidBand(int position) {
        for (int[] band : PLAID_BANDS) {
            if (position >= band[0] && position < band[1]) {
                return band;
            }
        }
        throw new IllegalStateException("no plaid band at " + position);
    }

    // Flower: petals where the polar radius r < 0.3 + 0.14 cos(5θ) about the center, a yellow disc
    // inside r < 0.1, on green; then the one-texel border, top and bottom rows over the corners.
    static BufferedImage flower(int side) {
        BufferedImage image = new BufferedImage(side, side, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < side; y++) {
            for (int x = 0; x < side; x++) {
                double px = (x + 0.5) / side - 0.5;
                double py = 0.5 - (y + 0.5) / side;
                double r = Math.hypot(px, py);
                double theta = Math.atan2(py, px);
                int color;
                if (r < 0.1) {
                    color = rgb(250, 210, 40);
                } else if (r < 0.3 + 0.14 * Math.cos(5 * theta)) {
                    color = rgb(235, 120, 170);
                } else {
                    color = rgb(70, 150, 70);
                }
                image.setRGB(x, y, framed(color, x, y, side));
            }
        }
        return image;
    }

    /**
     * The one-texel frame of the flower and the ruler: left column yellow, right white, top row red
     * and bottom blue, the rows over the corners; {@code inside} elsewhere.
     */
    private static int framed(int inside, int x, int y, int side) {
        if (y == 0) {
            return rgb(230, 20, 20);
        }
        if (y == side - 1) {
            return rgb(20, 40, 230);
        }
        if (x == 0) {
            return rgb(250, 230, 30);
        }
        return x == side - 1 ? rgb(255, 255, 255) : inside;
    }

    // Ruler: one texel per band, so a lookup one row or column off shows as a band of the wrong
    // height or color on the diagnostic chart.
    static BufferedImage ruler(int side) {
        BufferedImage image = new BufferedImage(side, side, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < side; y++) {
            for (int x = 0; x < side; x++) {
                int color = (x + y) % 2 == 0 ? rgb(30, 110, 40) : rgb(150, 220, 120);
                image.setRGB(x, y, framed(color, x, y, side));
            }
        }
        return image;
    }
}
