package ray.grading.wire;

/**
 * The layout of a batch ({@link Protocol#BATCH}) and of its answer, written and read in this order.
 *
 * <p>A batch, after its definitions:
 * <ol>
 * <li>intersects, by ray: a count of rays; for each, its origin and direction (three doubles each)
 * and start; its candidates, each a segment end and a record as it is before the call; and its
 * targets (twin references). The worker runs every target on every candidate, and adds candidates
 * of its own: for each hit at t, the ends t and the next double after t with the record as the hit
 * left it, which is what a search asks next ({@link #MAX_CANDIDATES} at most per ray);</li>
 * <li>generateRay calls: a count, then each target, u and v;</li>
 * <li>getTexColor calls: a count, then each target, u and v;</li>
 * <li>judge-side answers the worker may need (a student's group calling the judge's surfaces): a
 * count of base answers, each a judge handle, a ray (its seven numbers) and the answer to that ray
 * with an endless segment and a record of sentinel values, which the worker derives the answers for
 * shorter segments from by the {@link Answer} rule (only for surfaces the judge certified); then a
 * count of exact answers, each a judge handle, a ray with its end, a record, and the answer.</li>
 * </ol>
 *
 * <p>The answer: for each ray, the candidates the worker added (count, then each), then for each
 * target the index of its base answer (−1 for none) and that answer, and the candidates whose answer
 * the base's rule does not predict: a count, then each index with {@link #ANSWERED} and the answer,
 * or {@link #NEEDS} when it needs a judge-side answer it was not given (asked again next round);
 * then each generateRay answer (a status, then a ray or null, or what was thrown), each getTexColor
 * answer (a status, then a vector or null, or what was thrown); then the judge-side answers needed:
 * a count of rays for certified surfaces (handle and ray), a count of exact questions (handle, ray
 * with its end, record).
 */
public final class Batches {
    /** Candidates per ray the worker evaluates at most; beyond them, the judge asks in another round. */
    public static final int MAX_CANDIDATES = 24;
    public static final int ANSWERED = 0;
    public static final int NEEDS = 1;

    private Batches() {
    }
}
