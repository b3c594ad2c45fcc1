package ray.image;

import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import ray.math.Vec3;

/**
 * Reads a texture's image file (PNG, JPEG, GIF or BMP, whatever javax.imageio reads) into an
 * {@link Image} of texels: each is the file's 8-bit color divided by 255, with no sRGB decoding
 * (the course's convention), stored as every {@link Image} is, with j counting from the <b>bottom</b>
 * row; lookups read it by row from the top through {@code Texture.texel}. Alpha is ignored.
 *
 * <p>Every problem is an {@link IllegalArgumentException} whose message starts with "image", for
 * the scene loader to report at the {@code <image>} element's line.
 */
public final class TextureFiles {
    /** Largest side and texel count a texture may have: 16 million texels take 400 MB as doubles. */
    public static final int MAX_SIDE = 8192;
    public static final long MAX_TEXELS = 4096L * 4096L;
    /** Largest image file read: far above any texture within the texel limits, below what would strain the heap. */
    public static final long MAX_FILE_BYTES = 256L << 20;
    private static final String FORMATS = "a PNG, JPEG, GIF or BMP image";

    private TextureFiles() {
    }

    public static Image read(Path file) {
        byte[] bytes = bytesOf(file);
        if (bytes.length == 0) {
            throw problem("image file " + file + " is empty; expected " + FORMATS);
        }
        try (ImageInputStream in = ImageIO.createImageInputStream(new ByteArrayInputStream(bytes))) {
            Iterator<ImageReader> readers = ImageIO.getImageReaders(in);
            if (!readers.hasNext()) {
                throw problem("image file " + file + " is not an image this program can read; expected " + FORMATS);
            }
            ImageReader reader = readers.next();
            try {
                reader.setInput(in, true, true);
                // The size comes from the header, before any texel is decoded, so a huge image costs nothing.
                int width = reader.getWidth(0);
                int height = reader.getHeight(0);
                checkSize(file, width, height);
                return texels(reader.read(0));
            } finally {
                reader.dispose();
            }
        } catch (IOException | RuntimeException e) {
            if (e instanceof IllegalArgumentException && e.getMessage() != null && e.getMessage().startsWith("image")) {
                throw (IllegalArgumentException) e;
            }
            throw problem("image file " + file + " is damaged or unreadable (" + e.getMessage() + "); expected " + FORMATS);
        }
    }

    /**
     * The file's bytes, read whole before decoding so that a file that cannot be read is told apart
     * from one that is not an image (javax.imageio reports both as "no reader").
     */
    private static byte[] bytesOf(Path file) {
        if (!Files.exists(file)) {
            throw problem("image file " + file + " does not exist; expected " + FORMATS
                    + " (a relative path starts from the scene file's folder)");
        }
        if (!Files.isRegularFile(file)) {
            throw problem("image path " + file + " is not a regular file; expected " + FORMATS);
        }
        try {
            long size = Files.size(file);
            if (size > MAX_FILE_BYTES) {
                throw problem("image file " + file + " has " + size + " bytes; expected " + FORMATS + " of at most "
                        + MAX_FILE_BYTES + " bytes");
            }
            return Files.readAllBytes(file);
        } catch (IOException e) {
            String reason = e instanceof AccessDeniedException ? "permission denied"
                    // A FileSystemException's message starts with the path, which the sentence already names.
                    : e instanceof FileSystemException && ((FileSystemException) e).getReason() != null
                            ? ((FileSystemException) e).getReason() : String.valueOf(e.getMessage());
            throw problem("image file " + file + " cannot be read (" + reason + "); expected a readable image file");
        }
    }

    private static void checkSize(Path file, int width, int height) {
        if (width <= 0 || height <= 0) {
            throw problem("image file " + file + " has no texels (" + width + "×" + height + "); expected a nonempty image");
        }
        if (width > MAX_SIDE || height > MAX_SIDE || (long) width * height > MAX_TEXELS) {
            throw problem("image file " + file + " is " + width + "×" + height + ", too large for a texture; expected at most "
                    + MAX_SIDE + " texels a side and " + MAX_TEXELS + " in all");
        }
    }

    /** The decoded image as texels, rows flipped so that j counts from the bottom. */
    static Image texels(BufferedImage decoded) {
        int width = decoded.getWidth();
        int height = decoded.getHeight();
        Image texels = new Image(width, height);
        Raster raster = decoded.getRaster();
        // getRGB would convert a gray image from its linear gray color space to sRGB and so change its
        // values; a gray texel is its stored value instead.
        boolean gray = decoded.getColorModel().getColorSpace().getType() == java.awt.color.ColorSpace.TYPE_GRAY;
        double grayMax = gray ? (1 << decoded.getColorModel().getComponentSize(0)) - 1 : 0;
        for (int row = 0; row < height; row++) {
            int j = height - 1 - row;
            for (int i = 0; i < width; i++) {
                Vec3 color;
                if (gray) {
                    double level = Math.round(raster.getSample(i, row, 0) * 255 / grayMax) / 255.0;
                    color = new Vec3(level, level, level);
                } else {
                    int argb = decoded.getRGB(i, row);
                    color = new Vec3(((argb >> 16) & 0xFF) / 255.0, ((argb >> 8) & 0xFF) / 255.0, (argb & 0xFF) / 255.0);
                }
                texels.set(i, j, color);
            }
        }
        return texels;
    }

    private static IllegalArgumentException problem(String message) {
        return new IllegalArgumentException(message);
    }
}
