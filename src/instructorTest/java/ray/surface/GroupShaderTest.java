package ray.surface;

import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.math.Affine;
import ray.shading.Lambertian;
import ray.shading.Shader;

/** Checks shader inheritance ({@link ShaderInheritance}): a group's shader reaches children without one, and never replaces a child's own. */
public class GroupShaderTest {
    private final Shader groupShader = new Lambertian(v(1, 0, 0));
    private final Shader childShader = new Lambertian(v(0, 1, 0));

    @Test
    public void groupShaderGoesToChildrenWithoutOne() {
        Sphere plain = new Sphere();
        Sphere shaded = new Sphere();
        shaded.setShader(childShader);
        Group group = new Group();
        group.setShader(groupShader);
        group.addSurface(plain);
        group.addSurface(shaded);
        ShaderInheritance.apply(group, null);
        assertSame(groupShader, plain.getShader());
        assertSame(childShader, shaded.getShader());
    }

    @Test
    public void shaderReachesGrandchildrenThroughGroupsWithoutOne() {
        Sphere grandchild = new Sphere();
        Group middle = new Group();
        middle.addSurface(grandchild);
        Group top = new Group();
        top.setShader(groupShader);
        top.addSurface(middle);
        ShaderInheritance.apply(top, null);
        assertSame(groupShader, middle.getShader());
        assertSame(groupShader, grandchild.getShader());
    }

    @Test
    public void childGroupKeepsItsOwnShaderForItsChildren() {
        Sphere grandchild = new Sphere();
        Group middle = new Group();
        middle.setShader(childShader);
        middle.addSurface(grandchild);
        Group top = new Group();
        top.setShader(groupShader);
        top.addSurface(middle);
        ShaderInheritance.apply(top, null);
        assertSame(childShader, middle.getShader());
        assertSame(childShader, grandchild.getShader());
    }

    @Test
    public void shaderPassesThroughATransformedGroup() {
        Sphere grandchild = new Sphere();
        Group moved = new Group();
        moved.addSurface(grandchild);
        Surface wrapped = new Transformed(moved, Affine.translation(v(1, 0, 0)));
        Group top = new Group();
        top.setShader(groupShader);
        top.addSurface(wrapped);
        ShaderInheritance.apply(top, null);
        assertSame(groupShader, grandchild.getShader());
        assertSame(groupShader, wrapped.getShader());
    }

    @Test
    public void surfacesWithoutAShaderAboveThemTakeTheFallback() {
        Sphere child = new Sphere();
        Group group = new Group();
        group.addSurface(child);
        ShaderInheritance.apply(group, null);
        assertNull(child.getShader());
        // What a scene does for surfaces without a shader: inherit a default from the top.
        ShaderInheritance.apply(group, groupShader);
        assertSame(groupShader, child.getShader());
    }
}
