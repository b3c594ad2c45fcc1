package ray.grading;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;

/**
 * A grading's hold on a student user: while it holds the claim, no other grading on this machine (in
 * this JVM or another one, say two instructors' runs as root at once) runs code as that user, so
 * ending every process of the user ends this grading's alone. A claim is a lock on a file named after
 * the user in a folder only root may write, which the kernel releases when the claiming JVM ends,
 * however it ends.
 */
final class UserClaim implements AutoCloseable {
    /**
     * Where the lock files are: a folder of root's own (mode 700), made anew if anyone else made it; the
     * same for every grader on the machine, whatever its java.io.tmpdir (Gradle gives its tests their own).
     */
    static final Path FOLDER = Path.of("/tmp", "ray1-grading-users");

    /** The users this JVM's gradings hold. */
    private static final java.util.Set<String> HELD_HERE = new java.util.HashSet<>();

    private final String user;
    private final FileChannel channel;
    private final FileLock lock;

    private UserClaim(String user, FileChannel channel, FileLock lock) {
        this.user = user;
        this.channel = channel;
        this.lock = lock;
    }

    /** The claim on {@code user}, or null while another grading holds it. */
    static UserClaim tryClaim(String user) throws IOException {
        synchronized (HELD_HERE) {
            // Another grading of this JVM holds it: asked before the file, since closing any channel to a
            // locked file would release this JVM's lock on it.
            if (!HELD_HERE.add(user)) {
                return null;
            }
        }
        FileChannel channel = null;
        try {
            channel = FileChannel.open(privateFolder().resolve(user + ".lock"), StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                    LinkOption.NOFOLLOW_LINKS);
            FileLock lock = channel.tryLock();
            if (lock != null) {
                return new UserClaim(user, channel, lock);
            }
        } catch (OverlappingFileLockException e) {
            // Cannot happen (this JVM's claims are in HELD_HERE); treated as held.
        } catch (IOException | RuntimeException e) {
            release(user, channel);
            throw e;
        }
        release(user, channel);
        return null;
    }

    private static void release(String user, FileChannel channel) throws IOException {
        try {
            if (channel != null) {
                channel.close();
            }
        } finally {
            synchronized (HELD_HERE) {
                HELD_HERE.remove(user);
            }
        }
    }

    /**
     * The lock folder, owned by this process's user with no one else's access. One that is not (made by
     * a student's code beforehand, in a temporary folder everyone may write) is removed and made again,
     * so that no one else can hold or remove a lock file.
     */
    private static synchronized Path privateFolder() throws IOException {
        for (int attempt = 0; attempt < 10; attempt++) {
            try {
                Files.createDirectory(FOLDER, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
            } catch (java.nio.file.FileAlreadyExistsException e) {
                // Check it below.
            }
            Object owner = Files.getAttribute(FOLDER, "unix:uid", LinkOption.NOFOLLOW_LINKS);
            Object me = Files.getAttribute(Path.of("/proc/self"), "unix:uid");
            boolean ours = Files.isDirectory(FOLDER, LinkOption.NOFOLLOW_LINKS) && owner.equals(me)
                    && PosixFilePermissions.toString(Files.getPosixFilePermissions(FOLDER, LinkOption.NOFOLLOW_LINKS)).equals("rwx------");
            if (ours) {
                return FOLDER;
            }
            if (Files.isDirectory(FOLDER, LinkOption.NOFOLLOW_LINKS)) {
                ProjectTree.deleteRecursively(FOLDER);
            } else {
                Files.deleteIfExists(FOLDER); // a link or a file: removed itself, never what it points to
            }
        }
        throw new IOException(FOLDER + " keeps being made by someone else; cannot claim a student user");
    }

    /** Gives the user back to other gradings. */
    @Override
    public void close() throws IOException {
        try {
            lock.release();
        } finally {
            release(user, channel);
        }
    }
}
