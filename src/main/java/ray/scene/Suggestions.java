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

    /** Levenshtein distance by the two-row dynamic program. */
    static int editDistance(String a, String b) {
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
            }
            int[] swap = previous;
            previous = current;
            current = swap;
        }
        return previous[b.length()];
    }
}
