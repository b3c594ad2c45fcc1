package ray.grading;

/** One student of a submission, as Gradescope's export names them (any field may be empty). */
public record Submitter(String name, String email, String sid) {
}
