package ray.scene;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.function.UnaryOperator;
import ray.IntersectionRecord;
import ray.camera.Camera;
import ray.math.Vec3;
import ray.shading.BrdfShader;
import ray.shading.Course;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.shading.MicrofacetBrdfParameters;
import ray.shading.Shader;
import ray.shading.Texture;
import ray.shading.legacy.MicrofacetBrdfElement;
import ray.surface.Group;
import ray.surface.HitGeometry;
import ray.surface.Placements;
import ray.surface.ShaderInheritance;
import ray.surface.Surface;

/** Everything a render needs: camera, image size, lights, surfaces and output settings. */
public class Scene {
    private String name = "scene";
    /** The file the scene was loaded from and how, for loading it again another way ({@link #reload}); null for a scene made in code. */
    private Path file;
    private SceneOptions options;
    private Camera camera;
    private int width;
    private int height;
    private double exposure = 1.0;
    private Vec3 backColor = Vec3.ZERO;
    private int samples = 1;
    /** The course conventions it was completed by: they decide its shaders, and under 2019 the longest path. */
    private Course course = Course.Y2017;
    private final List<Light> lights = new ArrayList<>();
    private final List<Shader> shaders = new ArrayList<>();
    private final List<Texture> textures = new ArrayList<>();
    private final Group surfaces = new Group();
    /** The loader's warnings, each a located line: see {@link #warnings()}. */
    private final List<String> warnings = new ArrayList<>();
    /** Where the primitives sit, for {@link #hitGeometry}; made when first asked for after the last surface is added. */
    private volatile Placements placements;
    /** This scene seen from a camera at the origin, made when first rendered; dropped by any change. */
    private volatile Scene cameraFrame;

    public void setCamera(Camera camera) {
        cameraFrame = null;
        this.camera = camera;
    }

    public void setImage(int width, int height) {
        cameraFrame = null;
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("image size is " + width + " " + height + "; expected two positive integers");
        }
        String tooLarge = Limits.imageSizeProblem(width, height);
        if (tooLarge != null) {
            throw new IllegalArgumentException(tooLarge);
        }
        this.width = width;
        this.height = height;
    }

    public void setExposure(double exposure) {
        cameraFrame = null;
        if (!(exposure >= 0) || Double.isInfinite(exposure)) {
            throw new IllegalArgumentException("exposure is " + exposure + "; expected a number ≥ 0");
        }
        this.exposure = exposure;
    }

    public void setBackColor(Vec3 backColor) {
        cameraFrame = null;
        this.backColor = backColor;
    }

    public void setSamples(int samples) {
        cameraFrame = null;
        if (samples <= 0) {
            throw new IllegalArgumentException("samples is " + samples + "; expected a positive integer");
        }
        String tooMany = Limits.samplesProblem(samples);
        if (tooMany != null) {
            throw new IllegalArgumentException(tooMany);
        }
        this.samples = samples;
    }

    public void addLight(Light light) {
        cameraFrame = null;
        lights.add(light);
    }

    /** A named shader defined at the top level, for surfaces to reuse by ref. */
    public void addShader(Shader shader) {
        cameraFrame = null;
        shaders.add(shader);
    }

    /**
     * A named microfacet BRDF defined at the top level, as the older course scenes write one, for
     * their Microfacet shaders to reuse by ref; those shaders keep what they need of it.
     */
    public void addBrdf(MicrofacetBrdfElement brdf) {
        cameraFrame = null;
    }

    /** A named texture defined at the top level, for shaders to reuse by ref. */
    public void addTexture(Texture texture) {
        cameraFrame = null;
        textures.add(texture);
    }

    public synchronized void addSurface(Surface surface) {
        cameraFrame = null;
        surfaces.addSurface(surface);
        placements = null;
    }

    /** Checks that the scene can be rendered and gives a white Lambertian to every surface without a shader. */
    public void complete() {
        complete(Course.Y2017);
    }

    /**
     * As {@link #complete()}, the white Lambertian shaded by {@code course}'s conventions (under 2019
     * a {@link ray.shading.ReflectionShader} with ρd = 1).
     */
    public void complete(Course course) {
        if (camera == null) {
            throw new IllegalArgumentException(
                    "the scene has no <camera>; expected a camera, e.g. <camera type=\"PerspectiveCamera\"/>");
        }
        if (width == 0) {
            throw new IllegalArgumentException("the scene has no <image> size; expected <image>width height</image>");
        }
        ShaderInheritance.apply(surfaces, new Lambertian(Vec3.ONE).forCourse(course));
        this.course = course;
    }

    /** The course conventions the scene was completed by (2017's until it is). */
    public Course getCourse() {
        return course;
    }

    /**
     * A scene with this one's name, image, exposure, background, samples, shaders, textures and warnings, and
     * {@code camera}, {@code lights} and {@code surfaces} (the top level, under a root with this
     * scene's root shader) for its parts; this scene is left as it was. Not completed.
     */
    public Scene withParts(Camera camera, List<Light> lights, List<Surface> surfaces) {
        Scene copy = new Scene();
        copy.setName(name);
        copy.file = file;
        copy.options = options;
        copy.setCamera(camera);
        copy.setImage(width, height);
        copy.setExposure(exposure);
        copy.setBackColor(backColor);
        copy.setSamples(samples);
        copy.course = course;
        lights.forEach(copy::addLight);
        shaders.forEach(copy::addShader);
        textures.forEach(copy::addTexture);
        copy.surfaces.setShader(this.surfaces.getShader());
        surfaces.forEach(copy::addSurface);
        copy.warnings.addAll(warnings);
        return copy;
    }

    /**
     * The scene as the renderer sees it: moved so that the camera sits at the origin (see
     * {@link CameraFrame}), made once and kept until the scene changes; this scene itself when its
     * camera is already at the origin. Call it once every part is in place.
     */
    public Scene inCameraFrame() {
        Scene made = cameraFrame;
        if (made == null) {
            synchronized (this) {
                if (cameraFrame == null) {
                    cameraFrame = CameraFrame.of(this);
                }
                made = cameraFrame;
            }
        }
        return made;
    }

    /**
     * What the renderer needs to start new rays at {@code hit}, a closest hit that
     * {@code getSurfaces().intersect} reported: see {@link Placements}.
     */
    public HitGeometry hitGeometry(IntersectionRecord hit) {
        return placements().geometryOf(hit);
    }

    private Placements placements() {
        Placements made = placements;
        if (made == null) {
            synchronized (this) {
                if (placements == null) {
                    placements = Placements.of(surfaces);
                }
                made = placements;
            }
        }
        return made;
    }

    /** Notes where the loader read the scene from, and how. */
    void loadedFrom(Path file, SceneOptions options) {
        this.file = file;
        this.options = options;
    }

    /**
     * The scene loaded again from its file with the options {@code change} makes of those it was
     * loaded with (another course, BRDFs replaced): for comparing one scene rendered two ways.
     */
    public Scene reload(UnaryOperator<SceneOptions> change) {
        if (file == null) {
            throw new IllegalStateException("the scene " + name + " was not loaded from a file, so it cannot be loaded again");
        }
        return SceneLoader.load(file, change.apply(options));
    }

    /** Whether a surface of the scene is shaded by a microfacet BRDF (a MicrofacetBeckmann, MicrofacetGGX or Microfacet shader). */
    public boolean hasMicrofacetShader() {
        return hasMicrofacetShader(surfaces);
    }

    private static boolean hasMicrofacetShader(Surface surface) {
        if (surface.getShader() instanceof BrdfShader && ((BrdfShader) surface.getShader()).brdf() instanceof MicrofacetBrdfParameters) {
            return true;
        }
        for (Surface child : surface.children()) {
            if (hasMicrofacetShader(child)) {
                return true;
            }
        }
        return false;
    }

    public String getName() {
        return name;
    }

    public void setName(String name) {
        cameraFrame = null;
        this.name = name;
    }

    public Camera getCamera() {
        return camera;
    }

    public int getWidth() {
        return width;
    }

    public int getHeight() {
        return height;
    }

    public double getExposure() {
        return exposure;
    }

    public Vec3 getBackColor() {
        return backColor;
    }

    public int getSamples() {
        return samples;
    }

    public List<Light> getLights() {
        return Collections.unmodifiableList(lights);
    }

    public List<Texture> getTextures() {
        return Collections.unmodifiableList(textures);
    }

    public List<Shader> getShaders() {
        return Collections.unmodifiableList(shaders);
    }

    /**
     * What the loader found worth a remark in the scene file though the scene loads and renders, in
     * file order: one line each, {@code FILE:LINE:COL: warning: what}, e.g. a box given with minPt
     * above maxPt on an axis. The commands that load a scene print each on stderr. Read-only.
     */
    public List<String> warnings() {
        return Collections.unmodifiableList(warnings);
    }

    /** Adds a located warning line (not a public adder: the loader binds those to scene elements). */
    void warn(String line) {
        warnings.add(line);
    }

    /** All surfaces of the scene, as one group. */
    public Group getSurfaces() {
        return surfaces;
    }
}
