package ray.grading.judge;

import ray.surface.Surface;

/**
 * Which judge-side surfaces answer exactly as the contract says, so that a batch may send one answer
 * for a ray and let the worker derive the answers for shorter segments (see ray.grading.judge.Rounds):
 * none yet.
 */
class Certification {
    boolean certified(Surface surface) {
        return false;
    }
}
