package ray.surface;

import java.util.List;

/**
 * An object that a scene file can describe in a way that loads but deserves a remark: the scene
 * loader asks it, once it is completed, for its warnings and records each with the place of the
 * element that made it ({@code ray.scene.Scene#warnings()}). A warning never stops the scene from
 * loading or rendering; a mistake that should is an exception from {@code complete()} instead.
 *
 * <p>Deliberately not a setter or adder: the loader binds public {@code set*} and {@code add*}
 * methods to elements of the scene file.
 */
public interface WarnsOnLoad {
    /** One line per remark, without a location (the loader adds it); empty when there is nothing to say. */
    List<String> warnings();
}
