package ray.variants;

import java.net.URL;
import java.net.URLClassLoader;

/**
 * Loads the project's classes ({@code ray.*}) afresh, child first, from a variant's compiled
 * student files and then the build's own class folders, so that every framework class and test
 * links against the variant's {@code Sphere} (say) instead of the solution's; libraries (JUnit,
 * picocli) come from the parent and are shared.
 */
final class VariantLoader extends URLClassLoader {
    VariantLoader(URL[] urls, ClassLoader parent) {
        super(urls, parent);
    }

    @Override
    protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
        if (!name.startsWith("ray.")) {
            return super.loadClass(name, resolve);
        }
        synchronized (getClassLoadingLock(name)) {
            Class<?> c = findLoadedClass(name);
            if (c == null) {
                c = findClass(name);
            }
            if (resolve) {
                resolveClass(c);
            }
            return c;
        }
    }
}
