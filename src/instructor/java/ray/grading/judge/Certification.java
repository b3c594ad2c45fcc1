package ray.grading.judge;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import ray.surface.Surface;

/**
 * Which judge-side surfaces answer as the contract says, so that the worker may derive their answers
 * to a ray's shorter segments from one answer with an endless segment ({@link ray.grading.wire.Answer}'s
 * rule) instead of asking the judge for each: a surface certified here is of a class of the
 * framework or of the solution (its source is under src/main/java), is not of the class graded now,
 * and holds only such surfaces. A test's own surfaces (a fixed-hit surface, a hidden test's) are never certified:
 * they may break the contract on purpose. That the framework's and the solution's surfaces keep it is
 * checked by the grader's own tests (CertifiedSurfacesTest).
 */
final class Certification {
    private final Map<Class<?>, Boolean> classes = new ConcurrentHashMap<>();
    private final Map<Surface, Boolean> surfaces = new IdentityHashMap<>();
    private final Map<Surface, Boolean> holding = new IdentityHashMap<>();

    synchronized boolean certified(Surface surface) {
        Boolean known = surfaces.get(surface);
        if (known == null) {
            known = !StudentCalls.isRemote(surface) && fromMain(surface.getClass()) && childrenCertified(surface);
            surfaces.put(surface, known);
        }
        return known;
    }

    private boolean childrenCertified(Surface surface) {
        for (Surface child : surface.children()) {
            if (!certified(child)) {
                return false;
            }
        }
        return true;
    }

    /** Whether the class (or the top-level class it is nested in) has its source under src/main/java. */
    private boolean fromMain(Class<?> type) {
        return classes.computeIfAbsent(type, t -> {
            Class<?> top = t;
            while (top.getEnclosingClass() != null) {
                top = top.getEnclosingClass();
            }
            // The judge runs in the instructor's tree (TestProcess makes it the working folder).
            Path source = Path.of("src", "main", "java").resolve(top.getName().replace('.', '/') + ".java");
            return Files.isRegularFile(source);
        });
    }

    /** Whether the surface is of a class graded now, or holds one (among its parts, at any depth). */
    synchronized boolean holdsStandIn(Surface surface) {
        Boolean known = holding.get(surface);
        if (known == null) {
            known = StudentCalls.isRemote(surface);
            for (Surface child : surface.children()) {
                known = known || holdsStandIn(child);
            }
            holding.put(surface, known);
        }
        return known;
    }

    /** Forgets the surfaces seen (the classes stay): the tests' objects come and go. */
    synchronized void forget() {
        surfaces.clear();
        holding.clear();
    }
}
