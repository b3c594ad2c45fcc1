package ray.shading;

import ray.math.Vec3;

/** The ideal diffuse BRDF of the course's 2019 conventions: it reflects the share ρd of what arrives, spread evenly over the hemisphere. */
public class LambertianBrdf extends LambertianBrdfFormula {

    public LambertianBrdf() {
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        // TODO(Task 9): return the Lambertian BRDF's value, the same for every pair of directions.
        //   Return f(l, v): the share of the light arriving from l that leaves toward v, per unit of solid
        //   angle; a matte surface sends the share rhoD of what it receives evenly into the hemisphere.
        //   Conventions (the reference images depend on them):
        //   - rhoD is the diffuse reflectance (the shader's diffuse color, or its texture's color at the
        //     point), per channel; n, l and v are unit vectors (the normal, toward the light, toward the eye).
        //   - The shader multiplies f by the light's intensity, max(0, n·l) and 1/r²: f itself has no cosine.
        //   - Spread evenly, the reflected share integrates to rhoD over the hemisphere, which takes a 1/π.
        // HINTS steps
        //   1) Divide the diffuse reflectance by π and return it; the directions do not matter.
        // HINTS formulas
        //   1) f = ρd/π: return rhoD.times(1 / Math.PI).
        // END HINTS
        // BEGIN SOLUTION
        return rhoD.times(1 / Math.PI);
        // END SOLUTION
        // STUB: return Vec3.ZERO;
    }
}
