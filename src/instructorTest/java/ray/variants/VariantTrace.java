package ray.variants;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.URL;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Runs {@code ray1 trace SCENE X Y} in this JVM with a {@link Variant}'s files in place of the
 * solution's, as a student whose code is that variant would run it: the variant is compiled and
 * every {@code ray.*} class loaded afresh with it ({@link VariantLoader}), as for grading.
 */
final class VariantTrace {
    private VariantTrace() {
    }

    /** What the trace prints (its standard output and error, in that order). */
    static String of(Variant variant, Path work, String scene, int x, int y) throws Exception {
        return of(variant, work, scene, x, y, new String[0]);
    }

    /** As {@link #of(Variant, Path, String, int, int)}, with {@code options} before the scene ("--course", "2019"). */
    static String of(Variant variant, Path work, String scene, int x, int y, String[] options) throws Exception {
        Path classes = VariantGrading.compile(variant, work);
        List<URL> urls = new ArrayList<>();
        urls.add(classes.toUri().toURL());
        for (String entry : VariantGrading.classPath()) {
            urls.add(Path.of(entry).toUri().toURL());
        }
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        try (VariantLoader loader = new VariantLoader(urls.toArray(new URL[0]), VariantTrace.class.getClassLoader());
             PrintWriter o = new PrintWriter(out);
             PrintWriter e = new PrintWriter(err)) {
            Class<?> command = Class.forName("ray.cli.Ray1Command", true, loader);
            command.getMethod("run", PrintWriter.class, PrintWriter.class, String[].class)
                    .invoke(null, o, e, traceArguments(options, scene, x, y));
        }
        return out + err.toString();
    }

    private static String[] traceArguments(String[] options, String scene, int x, int y) {
        java.util.List<String> args = new java.util.ArrayList<>();
        args.add("trace");
        args.addAll(java.util.List.of(options));
        args.addAll(java.util.List.of(scene, String.valueOf(x), String.valueOf(y)));
        return args.toArray(new String[0]);
    }
}
