package ray.grading.boot;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.util.Arrays;

/**
 * The test JVM's entry point when student code is graded: reads the tree's files from standard input
 * (see {@link #read}), defines them in memory ({@link InMemoryClasses}) and runs {@code args[0]}'s
 * main with the other arguments. Only this package and the public libraries are on the class path,
 * so the student's user never needs read access to the grader's classes.
 *
 * <p>The stream: for each file, {@code true}, its resource name (writeUTF), its length (writeInt) and
 * its bytes; then {@code false}. The grader writes it ({@code ray.grading.Sandbox}).
 */
public final class InMemoryMain {
    private InMemoryMain() {
    }

    public static void main(String[] args) throws Throwable {
        if (args.length == 0) {
            System.err.println("usage: InMemoryMain MAIN-CLASS [ARGUMENT...] < files");
            System.exit(2);
        }
        InMemoryClasses classes = new InMemoryClasses(InMemoryMain.class.getClassLoader());
        read(System.in, classes);
        classes.defineAll();
        Thread.currentThread().setContextClassLoader(classes);
        Method main = Class.forName(args[0], false, classes).getMethod("main", String[].class);
        try {
            main.invoke(null, (Object) Arrays.copyOfRange(args, 1, args.length));
        } catch (InvocationTargetException e) {
            throw e.getCause();
        }
    }

    /** Reads the files of the stream into {@code classes}, until its end marker. */
    static void read(InputStream in, InMemoryClasses classes) throws IOException {
        DataInputStream data = new DataInputStream(new java.io.BufferedInputStream(in, 1 << 16));
        while (data.readBoolean()) {
            String name = data.readUTF();
            byte[] bytes = new byte[data.readInt()];
            data.readFully(bytes);
            classes.add(name, bytes);
        }
    }
}
