package ray.inspect;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/** A running {@code ray1 explore}: the scene loaded and rendered, and its page served. */
public final class Explorer implements AutoCloseable {
    private final ExploreServer server;
    private final List<String> warnings;

    private Explorer(ExploreServer server, List<String> warnings) {
        this.server = server;
        this.warnings = warnings;
    }

    /**
     * Loads and renders {@code sceneFile} and serves it on 127.0.0.1:{@code port} (0: any free port).
     *
     * @param reference the image to compare with, or null for the scene's own reference, if any
     * @param options   the course conventions and scene root to load it with
     * @throws ray.scene.SceneException when the scene does not load
     * @throws java.net.BindException   when the port is taken
     */
    public static Explorer start(Path sceneFile, Path reference, int port) throws IOException {
        return start(sceneFile, reference, port, ray.scene.SceneOptions.ofAssignment());
    }

    /** As {@link #start(Path, Path, int)}, loading the scene as {@code options} say. */
    public static Explorer start(Path sceneFile, Path reference, int port, ray.scene.SceneOptions options) throws IOException {
        ExploreSession session = new ExploreSession(sceneFile, reference, options);
        session.reload();
        return new Explorer(ExploreServer.start(session, port), session.warnings());
    }

    /** The warnings of the scene as first loaded, one located line each (ray.scene.Scene#warnings()). */
    public List<String> warnings() {
        return warnings;
    }

    public int port() {
        return server.port();
    }

    /** The page's address, e.g. http://127.0.0.1:8123/. */
    public String url() {
        return server.url();
    }

    @Override
    public void close() {
        server.close();
    }
}
