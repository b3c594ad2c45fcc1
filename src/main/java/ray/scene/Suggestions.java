package ray.scene;

/** "Did you mean …?" for misspelled names: the closest candidate by edit distance, if it is close. */
final class Suggestions {
    private Suggestions() {
    }

    /**
     * The candidate nearest to {@code word} (ignoring case), or null when none is within a third of its
     * length. A candidate that differs only in case is suggested: names such as types and refs are
     * case-sensitive.
     */
    static String closest(String word, Iterable<String> candidates) {
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (String c : candidates) {
            int d = editDistance(word.toLowerCase(), c.toLowerCase());
            if (d < bestDistance) {
                bestDistance = d;
                best = c;
            }
        }
        return best != null && !best.equals(word) && bestDistance <= Math.max(1, word.length() / 3) ? best : null;
    }

    /**
     * The optimal string alignment distance: Levenshtein's insertions, deletions and substitutions,
     * plus the swap of two neighbouring letters as one edit. Swapped letters are the commonest slip
     * ("bleu" for "blue"); counted as two edits they would put a short name out of reach.
     */
    static int editDistance(String a, String b) {
        // Three rows of the dynamic program: a swap looks two rows back.
        int[] beforePrevious = new int[b.length() + 1];
        int[] previous = new int[b.length() + 1];
        int[] current = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            previous[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            current[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int substitution = previous[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                current[j] = Math.min(substitution, Math.min(previous[j], current[j - 1]) + 1);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    current[j] = Math.min(current[j], beforePrevious[j - 2] + 1);
                }
            }
            int[] oldest = beforePrevious;
            beforePrevious = previous;
            previous = current;
            current = oldest;
        }
        return previous[b.length()];
    }
}
