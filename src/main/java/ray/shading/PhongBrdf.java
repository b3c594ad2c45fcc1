package ray.shading;

import ray.math.Vec3;

/**
 * The course's 2019 "modified Blinn–Phong" BRDF: a diffuse part ρd/π and a highlight ks·max(0, n·h)^p
 * with the half vector h. Its ks and p are kept by PhongBrdfParameters.
 */
public class PhongBrdf extends PhongBrdfParameters {

    public PhongBrdf() {
    }

    public PhongBrdf(Vec3 specularColor, double exponent) {
        super(specularColor, exponent);
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        // TODO(Task 9): return this Phong BRDF's value for light arriving from l and leaving toward v.
        //   Return f(l, v): a matte part (as the Lambertian BRDF's) plus a highlight that is brightest
        //   where the direction halfway between l and v lines up with the normal.
        //   Conventions (the reference images depend on them):
        //   - rhoD is the diffuse reflectance, per channel; n, l and v are unit vectors (the normal, toward
        //     the light, toward the eye); the highlight's color is getSpecularColor(), its exponent getExponent().
        //   - The highlight has no normalising factor, and f has no cosine: the shader multiplies all of f
        //     by the light's intensity, max(0, n·l) and 1/r².
        //   - A half vector below the surface gives no highlight (never a negative one).
        // HINTS steps
        //   1) Find the unit vector halfway between l and v.
        //   2) Take the cosine between it and the normal, no less than zero, to the power of the exponent.
        //   3) Return the diffuse reflectance over π plus the specular color times that power.
        // HINTS formulas
        //   1) h = (l + v) / |l + v|: l.plus(v).normalized().
        //   2) s = max(0, n·h)^p, with p = getExponent().
        //   3) f = ρd/π + ks · s, with ks = getSpecularColor().
        // END HINTS
        // BEGIN SOLUTION
        Vec3 sum = l.plus(v);
        // l = −v has no half vector; the shader never asks (such a light is below the surface
        // whenever the eye is above it), so the highlight there is taken as none.
        double highlight = sum.lengthSquared() == 0 ? 0 : Math.pow(Math.max(0, n.dot(sum.normalized())), getExponent());
        return rhoD.times(1 / Math.PI).plus(getSpecularColor().times(highlight));
        // END SOLUTION
        // STUB: return Vec3.ZERO;
    }
}
