package ray.shading;

/**
 * What the framework keeps of the ideal diffuse BRDF ({@link LambertianBrdf}, whose {@code value}
 * students write under the 2019 conventions): its formula as {@code ray1 trace} writes it.
 */
public abstract class LambertianBrdfFormula implements Brdf {
    @Override
    public String formula() {
        return "ρd/π";
    }
}
