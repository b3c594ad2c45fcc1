package ray.fuzz;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code gradle fuzz}: the long fuzz run. Prints the summary, writes it to OUT/fuzz-summary.md with
 * the damaged files of any failed case under OUT/failures/, and exits 1 when a case failed.
 */
@Command(name = "fuzz", mixinStandardHelpOptions = true, description = "Fuzzes the scene loader and renderer.")
public final class FuzzMain implements Callable<Integer> {
    @Option(names = "--cases", paramLabel = "N", defaultValue = "100000", description = "Cases to run (default: ${DEFAULT-VALUE}).")
    long cases;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "1", description = "Seed (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--threads", paramLabel = "N", description = "Workers (default: one per core).")
    Integer threads;

    @Option(names = "--scenes", paramLabel = "DIR", defaultValue = "scenes", description = "The corpus (default: ${DEFAULT-VALUE}).")
    Path scenes;

    @Option(names = {"-o", "--output"}, paramLabel = "DIR", defaultValue = "build/fuzz", description = "Output folder (default: ${DEFAULT-VALUE}).")
    Path output;

    @Option(names = "--replay", paramLabel = "N", description = "Run only case N of the seed: write its damaged file under"
            + " OUT/case-N/ and print how it ended.")
    Long replay;

    public static void main(String[] args) {
        System.exit(new CommandLine(new FuzzMain()).execute(args));
    }

    @Override
    public Integer call() throws Exception {
        if (replay != null) {
            Corpus corpus = Corpus.of(scenes);
            return replay(corpus, FuzzCase.of(corpus, seed, replay));
        }
        int workers = threads != null ? threads : Runtime.getRuntime().availableProcessors();
        Path work = Files.createTempDirectory("ray1-fuzz");
        Fuzzer fuzzer = new Fuzzer(Corpus.of(scenes), work, seed, workers, output.resolve("failures"));
        FuzzSummary summary = fuzzer.run(cases);
        String report = summary.markdown();
        Files.createDirectories(output);
        Files.writeString(output.resolve("fuzz-summary.md"), report, StandardCharsets.UTF_8);
        System.out.print(report);
        return summary.failed() == 0 && summary.done() == cases ? 0 : 1;
    }

    private int replay(Corpus corpus, FuzzCase c) throws Exception {
        Path kept = output.resolve("case-" + c.index).resolve(c.target.toString());
        Files.createDirectories(kept.getParent());
        byte[] damaged = CaseRunner.damaged(corpus, c);
        Files.write(kept, damaged);
        Path work = Files.createTempDirectory("ray1-fuzz");
        corpus.copyTo(work);
        Outcome o = new CaseRunner(corpus, work).run(c, damaged);
        System.out.println(c + "\n  damaged file: " + kept + "\n  " + o.kind
                + (o.message != null ? ": " + o.message : "") + (o.nonFinitePixels > 0 ? ", " + o.nonFinitePixels
                + " pixels not finite" : ""));
        return o.kind == Outcome.Kind.FAILED ? 1 : 0;
    }
}
