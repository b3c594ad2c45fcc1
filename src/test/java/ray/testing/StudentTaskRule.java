package ray.testing;

import java.util.concurrent.TimeUnit;
import org.junit.rules.TestRule;
import org.junit.rules.Timeout;
import org.junit.runner.Description;
import org.junit.runners.model.Statement;
import ray.bvh.BrokenTree;

/**
 * The rule every graded test class uses: a time limit per test (an infinite loop in student code
 * costs that test only; when grading, it also ends its task's run, see {@link UnfinishedTasks}), and
 * failure messages that say which task failed and where to work.
 *
 * <pre>{@code @Rule public final StudentTaskRule task = StudentTaskRule.of(getClass());}</pre>
 *
 * <p>The test class's task is the one whose test patterns in the table of tasks match its name.
 *
 * <p>A failure reads "[Task 2 (Sphere)] what went wrong", or "[Task 2 (Sphere), bonus] ..." for a
 * test whose {@link Points} says {@code bonus = true} or whose task is extra credit, so that a student sees at once that a
 * failure costs no regular points.
 */
public final class StudentTaskRule implements TestRule {
    /** Seconds a unit test of student code may take: a correct solution needs milliseconds. */
    public static final int UNIT_TEST_SECONDS = 10;

    private final StudentTask task;
    private final int seconds;

    private StudentTaskRule(StudentTask task, int seconds) {
        this.task = task;
        this.seconds = seconds;
    }

    /** The rule of a test class: its task is the one the table of tasks gives that class. */
    public static StudentTaskRule of(Class<?> testClass) {
        return new StudentTaskRule(StudentTask.ofTestClass(testClass), UNIT_TEST_SECONDS);
    }

    /** The same rule with a longer limit, e.g. for whole-scene renders. */
    public StudentTaskRule withTimeoutSeconds(int limit) {
        return new StudentTaskRule(task, limit);
    }

    public StudentTask task() {
        return task;
    }

    @Override
    public Statement apply(Statement base, Description description) {
        boolean bonus = task.extraCredit || isBonus(description);
        String label = labelOf(task, bonus);
        Statement limited = Timeout.builder().withTimeout(seconds, TimeUnit.SECONDS).withLookingForStuckThread(true)
                .build().apply(base, description);
        // A hidden test is not named to the student, not even by its method.
        String test = isHidden(description) ? "a hidden test" : "test " + simpleName(description) + "." + description.getMethodName();
        return new Statement() {
            @Override
            public void evaluate() throws Throwable {
                UnfinishedTasks.entered(description.getClassName() + "#" + description.getMethodName());
                Hints.running(task);
                String skipped = UnfinishedTasks.skipped(task, bonus);
                if (skipped != null) {
                    throw new AssertionError(skipped);
                }
                try {
                    limited.evaluate();
                } catch (NotThisTasksFault e) {
                    NotThisTasksFault labelled = new NotThisTasksFault(label + e.getMessage());
                    labelled.setStackTrace(e.getStackTrace());
                    throw labelled;
                } catch (AssertionError e) {
                    throw explained(label, e.getMessage(), e);
                } catch (org.junit.runners.model.TestTimedOutException e) {
                    throw timedOut(label, bonus, test, e);
                } catch (org.junit.runners.model.MultipleFailureException e) {
                    // A time-out together with the threads JUnit found stuck (ones the code started): still a time-out.
                    if (e.getFailures().stream().anyMatch(f -> f instanceof org.junit.runners.model.TestTimedOutException)) {
                        throw timedOut(label, bonus, test, e);
                    }
                    throw thrown(e, bonus);
                } catch (Exception | VirtualMachineError | LinkageError e) {
                    throw thrown(e, bonus);
                }
            }
        };
    }

    /**
     * The failure of a test whose code threw {@code e}: reported under the task whose file threw it,
     * whichever task's test ran it (a render test runs several), with a first line that does not
     * depend on the test: the summary then names one exception once (gradle/test-report.gradle).
     */
    private AssertionError thrown(Throwable e, boolean bonus) {
        StudentTask thrower = StudentFrames.taskWhoseFileThrew(e instanceof ExceptionInInitializerError && e.getCause() != null ? e.getCause() : e);
        StudentTask blamed = thrower == null ? task : thrower;
        return explained(labelOf(blamed, bonus), whatWentWrong(e), e, blamed);
    }

    /** The failure of a test that ran out of time; the task's later tests are skipped when grading ({@link UnfinishedTasks}). */
    private AssertionError timedOut(String label, boolean bonus, String test, Exception e) {
        UnfinishedTasks.didNotFinish(task, bonus, test);
        return explained(label, "took longer than " + seconds + " s: is there a loop that never ends?", e);
    }

    /** "[Task 2 (Sphere)] " or "[Task 2 (Sphere), bonus] ", which starts a failure's message. */
    private static String labelOf(StudentTask task, boolean bonus) {
        return "[" + task.label() + (bonus ? ", bonus" : "") + "] ";
    }

    private static String simpleName(Description description) {
        String name = description.getClassName();
        return name.substring(name.lastIndexOf('.') + 1);
    }

    /** Whether the test's own @Points, or else its class's, marks it as a bonus test. */
    private static boolean isBonus(Description description) {
        Points points = pointsOf(description);
        return points != null && points.bonus();
    }

    private static boolean isHidden(Description description) {
        Points points = pointsOf(description);
        return points != null && points.visibility() == Visibility.HIDDEN;
    }

    /** The test's own @Points, or else its class's, or null. */
    private static Points pointsOf(Description description) {
        Points points = description.getAnnotation(Points.class);
        if (points == null && description.getTestClass() != null) {
            points = description.getTestClass().getAnnotation(Points.class);
        }
        return points;
    }

    /**
     * The failure, labelled, with where to work. An assertion's own message says it all, so it is not
     * kept as the cause (Gradle would print it a second time); an exception from student code is,
     * for its stack trace.
     */
    private AssertionError explained(String label, String message, Throwable cause) {
        return explained(label, message, cause, task);
    }

    private static AssertionError explained(String label, String message, Throwable cause, StudentTask blamed) {
        AssertionError error = new AssertionError(label + message + workOn(blamed), cause instanceof AssertionError ? null : cause);
        error.setStackTrace(cause.getStackTrace());
        return error;
    }

    static String workOn(StudentTask task) {
        return "\n    Work on the TODO(Task " + task.number + ") comments in " + String.join(" and ", task.files) + ".";
    }

    /**
     * What the code did, named as what it is: running out of memory or stack and a class that could
     * not be set up are not ordinary exceptions, and a student should not have to decode them.
     */
    public static String whatWentWrong(Throwable e) {
        if (e instanceof OutOfMemoryError) {
            return "your code ran out of memory (" + e + ")" + where(e)
                    + ": does it keep allocating, say a list that grows in a loop or a huge array?";
        }
        if (e instanceof StackOverflowError) {
            return "your code ran out of stack (StackOverflowError)" + where(e) + ": does a method call itself without end?";
        }
        if (e instanceof ExceptionInInitializerError) {
            Throwable cause = e.getCause() == null ? e : e.getCause();
            return "a static initializer in your code threw " + cause + where(cause);
        }
        if (e instanceof NoClassDefFoundError && String.valueOf(e.getMessage()).startsWith("Could not initialize class")) {
            return "your class " + e.getMessage().substring("Could not initialize class ".length())
                    + " cannot be used: its static initializer failed in an earlier test (see that test's message)";
        }
        if (e instanceof VirtualMachineError) {
            return "the Java VM gave up running your code (" + e + ")" + where(e);
        }
        if (e instanceof BrokenTree) {
            return "the framework cannot search with your tree: " + e.getMessage();
        }
        return "your code threw " + e + where(e);
    }

    /** " at Sphere.java:57" for the first frame in the project's own code, if any. */
    private static String where(Throwable e) {
        for (StackTraceElement frame : e.getStackTrace()) {
            // The test harness, the grader and the hidden tests are not the student's code.
            String c = frame.getClassName();
            if (c.startsWith("ray.") && !c.startsWith("ray.testing.") && !c.startsWith("ray.grading.") && !c.startsWith("ray.hidden.")) {
                return " at " + frame.getFileName() + ":" + frame.getLineNumber();
            }
        }
        return "";
    }
}
