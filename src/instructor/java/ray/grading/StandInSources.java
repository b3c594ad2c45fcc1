package ray.grading;

import com.sun.source.tree.ClassTree;
import com.sun.source.tree.CompilationUnitTree;
import com.sun.source.tree.MethodTree;
import com.sun.source.tree.Tree;
import com.sun.source.tree.VariableTree;
import com.sun.source.util.JavacTask;
import com.sun.source.util.SourcePositions;
import com.sun.source.util.Trees;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URI;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;
import javax.tools.JavaCompiler;
import javax.tools.SimpleJavaFileObject;
import javax.tools.ToolProvider;

/**
 * The judge's class for a student class, written from the instructor's file itself (the solution,
 * whose markers are comments): the same class, whose methods that hold a {@code TODO(Task N)}
 * comment first ask whether task N is being graded, and then call the worker
 * (ray.grading.judge.StudentCalls) instead of running the solution, and with the members of
 * ray.grading.judge.StandIn added: the object's bookkeeping, a complete() that notes it ran, and
 * whether its calls go to the worker. So one judge grades every task, each with the solution of
 * every other, and the stand-ins follow the student files with no list to keep: a new task's file gets
 * its stand-in as long as each of its methods is one StudentCalls can forward ({@link #FORWARDS}).
 */
final class StandInSources {
    /** The student methods the judge can forward, by name and parameter count, and StudentCalls' method for each. */
    static final Map<String, String> FORWARDS = Map.ofEntries(Map.entry("intersect/2", "intersect"), Map.entry("generateRay/2", "generateRay"),
            Map.entry("getTexColor/2", "texColor"), Map.entry("shade/4", "shade"), Map.entry("shadeRay/2", "shadeRay"),
            Map.entry("value/4", "brdfValue"), Map.entry("normalDistribution/2", "normalDistribution"), Map.entry("masking/3", "masking"),
            Map.entry("reflectance/1", "reflectance"), Map.entry("ofSphere/2", "ofSphere"), Map.entry("ofTriangle/3", "ofTriangle"),
            Map.entry("ofCylinder/3", "ofCylinder"),
            Map.entry("hit/2", "boxHit"), Map.entry("build/2", "build"), Map.entry("closestHit/3", "closestHit"),
            Map.entry("anyHit/2", "anyHit"));

    private StandInSources() {
    }

    /** The stand-in's source for the student file {@code path} of task {@code task}, whose instructor's version is {@code source}. */
    static String of(String instructorSource, String path, int task) {
        String stub = instructorSource;
        JavaCompiler compiler = ToolProvider.getSystemJavaCompiler();
        if (compiler == null) {
            throw new IllegalStateException("no Java compiler in this runtime: grading needs a JDK");
        }
        SimpleJavaFileObject file = new SimpleJavaFileObject(URI.create("string:///" + path), javax.tools.JavaFileObject.Kind.SOURCE) {
            @Override
            public CharSequence getCharContent(boolean ignoreEncodingErrors) {
                return stub;
            }
        };
        JavacTask parser = (JavacTask) compiler.getTask(null, null, d -> { }, List.of("--release", "17", "-proc:none"), null, List.of(file));
        CompilationUnitTree unit;
        try {
            unit = parser.parse().iterator().next();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        SourcePositions positions = Trees.instance(parser).getSourcePositions();
        String className = path.substring(path.lastIndexOf('/') + 1).replace(".java", "");
        ClassTree type = null;
        for (Tree t : unit.getTypeDecls()) {
            if (t instanceof ClassTree && ((ClassTree) t).getSimpleName().contentEquals(className)) {
                type = (ClassTree) t;
            }
        }
        if (type == null) {
            throw new IllegalStateException(path + " declares no class " + className);
        }
        // Every method that holds a TODO is the student's (a distribution's D and G1 are two in one file).
        List<MethodTree> studentMethods = new ArrayList<>();
        for (Tree member : type.getMembers()) {
            if (member instanceof MethodTree && ((MethodTree) member).getBody() != null) {
                MethodTree m = (MethodTree) member;
                String body = stub.substring((int) positions.getStartPosition(unit, m), (int) positions.getEndPosition(unit, m));
                if (body.contains("TODO(Task")) {
                    studentMethods.add(m);
                }
            }
        }
        if (studentMethods.isEmpty()) {
            throw new IllegalStateException(path + " has no method with a TODO(Task N) comment");
        }
        // Edits by position, made from the end so that earlier positions stay valid.
        TreeMap<Integer, String[]> edits = new TreeMap<>();
        boolean surface = false;
        for (MethodTree studentMethod : studentMethods) {
            List<String> parameters = studentMethod.getParameters().stream().map(v -> ((VariableTree) v).getName().toString())
                    .collect(Collectors.toList());
            String key = studentMethod.getName() + "/" + parameters.size();
            String forward = FORWARDS.get(key);
            if (forward == null) {
                throw new IllegalStateException(path + ": grading cannot forward " + studentMethod.getName() + " with " + parameters.size()
                        + " parameters to the worker; teach ray.grading.judge.StudentCalls to");
            }
            surface |= forward.equals("intersect");
            // Right after the method's opening brace: while task N is graded, the worker answers.
            int bodyStart = (int) positions.getStartPosition(unit, studentMethod.getBody()) + 1;
            String arguments = parameters.isEmpty() ? "" : ", " + String.join(", ", parameters);
            edits.put(bodyStart, new String[] {"", "\n        if (StudentCalls.remote(" + task + ")) {\n            return StudentCalls." + forward
                    + "(this" + arguments + ");\n        }"});
        }
        int classEnd = (int) positions.getEndPosition(unit, type) - 1;
        String packageName = unit.getPackageName() == null ? "" : unit.getPackageName().toString() + ".";
        edits.put(classEnd, new String[] {"", members(surface, task, packageName + className)});
        List<? extends Tree> interfaces = type.getImplementsClause();
        Tree after = interfaces.isEmpty() ? type.getExtendsClause() : interfaces.get(interfaces.size() - 1);
        if (after == null) {
            throw new IllegalStateException(path + ": " + className + " extends no framework class");
        }
        edits.put((int) positions.getEndPosition(unit, after),
                new String[] {"", (interfaces.isEmpty() ? " implements " : ", ") + "StandIn"});
        // Imports rather than qualified names: a parameter named ray hides the package ray.
        int importsAt = unit.getImports().isEmpty() ? (int) positions.getEndPosition(unit, unit.getPackage())
                : (int) positions.getEndPosition(unit, unit.getImports().get(unit.getImports().size() - 1));
        edits.put(importsAt, new String[] {"", "\nimport ray.grading.judge.StandIn;\nimport ray.grading.judge.StandInState;"
                + "\nimport ray.grading.judge.StudentCalls;"});
        StringBuilder source = new StringBuilder(stub);
        for (Map.Entry<Integer, String[]> edit : edits.descendingMap().entrySet()) {
            int at = edit.getKey();
            source.replace(at, at + edit.getValue()[0].length(), edit.getValue()[1]);
        }
        return "// The judge's stand-in for " + path + ", written by ray.grading.StandInSources: do not edit.\n" + source;
    }

    private static String members(boolean surface, int task, String studentClass) {
        List<String> lines = new ArrayList<>();
        lines.add("");
        lines.add("    @Override");
        lines.add("    public boolean ray1Remote() {");
        lines.add("        return StudentCalls.remote(" + task + ");");
        lines.add("    }");
        lines.add("");
        lines.add("    @Override");
        lines.add("    public String ray1StudentClass() {");
        lines.add("        return \"" + studentClass + "\";");
        lines.add("    }");
        lines.add("");
        lines.add("    private StandInState ray1State;");
        lines.add("");
        lines.add("    @Override");
        if (surface) {
            lines.add("    public ray.surface.Surface complete() {");
            lines.add("        ray.surface.Surface done = super.complete();");
            lines.add("        ray1StandIn().completed();");
            lines.add("        return done;");
        } else {
            lines.add("    public void complete() {");
            lines.add("        super.complete();");
            lines.add("        ray1StandIn().completed();");
        }
        lines.add("    }");
        lines.add("");
        lines.add("    @Override");
        lines.add("    public synchronized StandInState ray1StandIn() {");
        lines.add("        if (ray1State == null) {");
        lines.add("            ray1State = new StandInState(this);");
        lines.add("        } else if (ray1State.owner() != this) {");
        lines.add("            // A clone (the framework's moved copy): a twin of its own.");
        lines.add("            ray1State = ray1State.forClone(this);");
        lines.add("        }");
        lines.add("        return ray1State;");
        lines.add("    }");
        lines.add("");
        return String.join("\n", lines);
    }
}
