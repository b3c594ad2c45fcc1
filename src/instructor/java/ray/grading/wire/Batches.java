package ray.grading.wire;

/**
 * The layout of a batch ({@link Protocol#BATCH}) and of its answer, written and read in this order.
 *
 * <p>A batch, after its definitions:
 * <ol>
 * <li>its rays: a count, then each ray's origin, direction (three doubles each) and start; the rest
 * of the batch names a ray by its index here;</li>
 * <li>intersects, by ray: a count; for each, the ray's index, its candidates (each a segment end and a
 * record as it is before the call) and its targets (twin handles); the ray's index, the counts and the handles are varints. The worker runs every target on
 * every candidate, and, where a ray has several targets (up to {@link #MAX_SEARCHED}), adds candidates of its own: for each hit at
 * t, the ends t and the next double after t with the record as the hit left it, which is what a
 * search asks its next surface ({@link #MAX_CANDIDATES} at most per ray);</li>
 * <li>generateRay calls: a count, then each target, u and v;</li>
 * <li>getTexColor calls: a count, then each target, u and v;</li>
 * <li>any-hit questions (a shadow ray's "anything in the way?" of a set of the student's triangles): a
 * count, then each target's handle, a ray's index and a segment end (counts, handles and indices as
 * varints);</li>
 * <li>judge-side answers the student's code may need (a student's group calling the judge's
 * surfaces): a count of groups of base answers, each a ray's index, a count, and that many judge
 * handles each with its answer to that ray with an endless segment on a record of sentinel values, which the worker derives the answers for
 * shorter segments from by the {@link Answer} rule (sent only for surfaces the judge certified); then
 * a count of exact answers, each a judge handle, a ray's index, a segment end, a record and the
 * answer.</li>
 * </ol>
 *
 * <p>The answer: for each intersect ray, the ends of the candidates the worker added (count, then each),
 * then for each target {@link #ALL_MISSED}, or {@link #WITH_BASE}, the index of its base answer plus one (0 for
 * none) and that answer, and the candidates whose answer the base's rule does not predict: a count,
 * then each index with {@link #ANSWERED} and the answer, or {@link #NEEDS} when it needs a judge-side
 * answer it was not given (asked again next round), then for each added candidate the target and the
 * candidate whose hit it follows (its record is the record that hit left); counts and indices here
 * are varints; then each generateRay answer (a status, then a ray or null, or what was thrown) and each
 * getTexColor answer (a status, then a vector or null, or what was thrown), and each any-hit answer
 * (a status, then yes or no, or what was thrown, or {@link Protocol#NEED}); then the judge-side
 * answers needed: a count of base answers (handle and ray: seven numbers), a count of exact ones
 * (handle, ray with its end, record).
 */
public final class Batches {
    /** Candidates per ray the worker evaluates at most; beyond them, the judge asks in another round. */
    public static final int MAX_CANDIDATES = 24;
    /** Targets of a ray beyond which the worker adds no candidates: a search asks a few dozen surfaces a ray. */
    public static final int MAX_SEARCHED = 64;
    /*
     * An answer must fit one frame (Frames.MAX_FRAME_BYTES, 96 MB), however the student's code answers;
     * its parts are bounded so that they always do:
     *   the answers to what the judge asked:  at most ASKED_ANSWER_BYTES (the judge splits its questions so);
     *   whole throwables:                     THROWN_BYTES, plus the one that crosses it;
     *   the answers to candidates it added:   SPECULATED_BYTES, plus one ray's worth (MAX_CANDIDATES × MAX_SEARCHED answers);
     * 48 + 4 (+ 1) + 24 + 24 × 64 × 1.4 KB (2.2) ≈ 79 MB.
     */
    /**
     * Bytes one answer (an intersect's, a call's, an any-hit's, with the needed judge-side answer it
     * names) takes at most once the whole throwables are spent: a record with a foreign surface's name
     * (about 630), or a throwable in brief ({@link ThrownData#brief}, about 1,330).
     */
    public static final int ANSWER_BYTES_AT_MOST = 1400;
    /** The answers to a message's own questions, counted at {@link #ANSWER_BYTES_AT_MOST} each, stay below this. */
    public static final long ASKED_ANSWER_BYTES = 48L << 20;
    /** Bytes of whole throwables (with their frames and causes) one answer carries; later ones go in brief. */
    public static final long THROWN_BYTES = 4L << 20;
    /**
     * Once an answer holds this many bytes, the worker adds no more candidates of its own: they only
     * spare the judge a round, and an intersect that hits everywhere would make each ray's answers many.
     */
    public static final long SPECULATED_BYTES = 24L << 20;
    public static final int ANSWERED = 0;
    public static final int NEEDS = 1;
    /** A target's answers: it missed on every candidate and changed nothing (the usual answer, one byte). */
    public static final int ALL_MISSED = 0;
    /** A target's answers: a base answer and those its rule does not predict. */
    public static final int WITH_BASE = 1;

    private Batches() {
    }
}
