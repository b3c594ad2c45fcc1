package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertNull;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.Test;

/** One grading at a time holds a student user, in this JVM and across JVMs; giving it back frees it. */
public class UserClaimTest {
    private static final String USER = "ray1-claim-test-" + ProcessHandle.current().pid();

    @Test
    public void aUserIsHeldByOneGradingAtATime() throws Exception {
        try (UserClaim first = UserClaim.tryClaim(USER)) {
            assertNotNull(first);
            assertNull("a second grading in this JVM", UserClaim.tryClaim(USER));
            assertEquals("a grader in another JVM", "held", otherJvmTries());
        }
        try (UserClaim again = UserClaim.tryClaim(USER)) {
            assertNotNull("given back", again);
        }
        assertEquals("free again", "claimed", otherJvmTries());
    }

    /** A lock folder someone else made (with everyone's access) is not used: it is made again, this user's alone. */
    @Test
    public void aLockFolderOthersMayWriteIsMadeAgain() throws Exception {
        Path locks = UserClaim.FOLDER;
        try (UserClaim warmUp = UserClaim.tryClaim(USER)) {
            assertNotNull(warmUp);
        }
        Files.setPosixFilePermissions(locks, PosixFilePermissions.fromString("rwxrwxrwx"));
        Files.writeString(locks.resolve("planted"), "x");
        try (UserClaim claim = UserClaim.tryClaim(USER)) {
            assertNotNull(claim);
            assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(locks)));
            assertEquals(false, Files.exists(locks.resolve("planted")));
        }
    }

    /** What a JVM of its own gets when it tries the claim: "claimed" or "held". */
    private static String otherJvmTries() throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), UserClaimTest.class.getName(), USER)
                .redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes()).trim();
        p.waitFor();
        return out;
    }

    /** Tries the claim on args[0] and says how it went. */
    public static void main(String[] args) throws Exception {
        UserClaim claim = UserClaim.tryClaim(args[0]);
        System.out.println(claim == null ? "held" : "claimed");
        if (claim != null) {
            claim.close();
        }
    }
}
