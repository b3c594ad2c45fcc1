package ray.grading.boot;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.net.URLConnection;
import java.net.URLStreamHandler;
import java.util.Collections;
import java.util.Enumeration;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A class loader whose classes arrive as bytes, never as files: the grader hands the test JVM the
 * instructor's compiled tree (hidden tests included) this way, so no path the student's user can
 * read holds them. Every class is defined at once, before any test (or student code) runs, and the
 * bytes are then dropped: afterwards nothing in this loader, reflection included, gives them back.
 * Class files are not resources here ({@code getResource("X.class")} finds nothing); other files
 * (a web page the explorer serves, say) are.
 */
final class InMemoryClasses extends ClassLoader {
    static {
        registerAsParallelCapable();
    }

    /** Class bytes by binary name, until {@link #defineAll}; emptied then. */
    private final Map<String, byte[]> pending = new LinkedHashMap<>();
    /** Files that are not classes, by resource name ("ray/inspect/page.html"). */
    private final Map<String, byte[]> resources = new LinkedHashMap<>();

    InMemoryClasses(ClassLoader parent) {
        super("ray1-graded", parent);
    }

    /** Adds one file of the tree; the first of a name wins, as on a class path. */
    void add(String resourceName, byte[] bytes) {
        if (resourceName.endsWith(".class")) {
            String name = resourceName.substring(0, resourceName.length() - ".class".length()).replace('/', '.');
            pending.putIfAbsent(name, bytes);
        } else {
            resources.putIfAbsent(resourceName, bytes);
        }
    }

    /**
     * Defines every class handed over and forgets the bytes. A class that cannot be defined (its
     * superclass needs a library the tests do not have) is left out, as a class path would fail it on
     * first use.
     */
    void defineAll() {
        for (String name : new java.util.ArrayList<>(pending.keySet())) {
            try {
                loadClass(name);
            } catch (ClassNotFoundException | LinkageError e) {
                // Not needed by any graded test: its first use, if any, fails as it would on a class path.
            }
        }
        pending.clear();
    }

    @Override
    protected Class<?> findClass(String name) throws ClassNotFoundException {
        byte[] bytes;
        synchronized (pending) {
            bytes = pending.remove(name);
        }
        if (bytes == null) {
            throw new ClassNotFoundException(name);
        }
        return defineClass(name, bytes, 0, bytes.length);
    }

    @Override
    protected URL findResource(String name) {
        byte[] bytes = resources.get(name);
        if (bytes == null) {
            return null;
        }
        try {
            return new URL("ray1-memory", null, -1, "/" + name, new URLStreamHandler() {
                @Override
                protected URLConnection openConnection(URL url) {
                    return new URLConnection(url) {
                        @Override
                        public void connect() {
                        }

                        @Override
                        public InputStream getInputStream() {
                            return new ByteArrayInputStream(bytes);
                        }
                    };
                }
            });
        } catch (IOException e) {
            return null;
        }
    }

    @Override
    protected Enumeration<URL> findResources(String name) {
        URL url = findResource(name);
        return url == null ? Collections.emptyEnumeration() : Collections.enumeration(java.util.List.of(url));
    }
}
