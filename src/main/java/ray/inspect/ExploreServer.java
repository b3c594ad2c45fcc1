package ray.inspect;

import com.google.gson.JsonObject;
import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import ray.scene.SceneException;

/**
 * The explore page's web server, on the loopback address only (the JDK's
 * {@code com.sun.net.httpserver}). It serves a fixed set of paths: the page's three files from the
 * class path, and the API (documented in docs/cli.md): {@code GET /api/scene}, {@code /api/trace?x=&y=},
 * {@code /api/image.png}, {@code /api/reference.png}, {@code /api/diff.png} and
 * {@code POST /api/rerender}. No part of a request names a file, so it can serve nothing else.
 * Requests whose Host is not this machine's loopback name are refused, so a web page elsewhere
 * cannot reach the server through a DNS name that points here. One thread handles every request:
 * student code need not be thread-safe, and the session is never read while it renders.
 */
public final class ExploreServer implements AutoCloseable {
    /** The page's files: request path → class-path resource and content type. */
    private static final Map<String, String[]> PAGE = Map.of(
            "/", new String[] {"index.html", "text/html; charset=utf-8"},
            "/index.html", new String[] {"index.html", "text/html; charset=utf-8"},
            "/explore.js", new String[] {"explore.js", "text/javascript; charset=utf-8"},
            "/explore.css", new String[] {"explore.css", "text/css; charset=utf-8"});

    private final ExploreSession session;
    private final HttpServer server;
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "ray1-explore");
        t.setDaemon(true);
        return t;
    });

    private ExploreServer(ExploreSession session, HttpServer server) {
        this.session = session;
        this.server = server;
    }

    /**
     * Serves {@code session} (already loaded) on 127.0.0.1:{@code port}, 0 for any free port.
     *
     * @throws java.net.BindException when the port is taken
     */
    static ExploreServer start(ExploreSession session, int port) throws IOException {
        HttpServer http = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 0);
        ExploreServer explore = new ExploreServer(session, http);
        http.createContext("/", explore::handle);
        http.setExecutor(explore.worker);
        http.start();
        return explore;
    }

    int port() {
        return server.getAddress().getPort();
    }

    String url() {
        return "http://127.0.0.1:" + port() + "/";
    }

    @Override
    public void close() {
        server.stop(0);
        worker.shutdownNow();
    }

    private void handle(HttpExchange exchange) throws IOException {
        try (exchange) {
            if (!fromThisMachine(exchange)) {
                text(exchange, 403, "this server answers only requests to 127.0.0.1 or localhost");
                return;
            }
            URI uri = exchange.getRequestURI();
            String path = uri.getRawPath();
            String method = exchange.getRequestMethod();
            boolean post = path.equals("/api/rerender");
            if (!method.equals(post ? "POST" : "GET")) {
                exchange.getResponseHeaders().set("Allow", post ? "POST" : "GET");
                text(exchange, 405, path + " takes " + (post ? "POST" : "GET") + ", not " + method);
                return;
            }
            route(exchange, path, uri.getRawQuery());
        } catch (RuntimeException | StackOverflowError e) {
            // A failure of the server's own (student code's failures are caught where they run).
            text(exchange, 500, "ray1 explore failed: " + Failure.oneLine(e));
        }
    }

    private void route(HttpExchange exchange, String path, String query) throws IOException {
        String[] page = PAGE.get(path);
        if (page != null) {
            resource(exchange, page[0], page[1]);
            return;
        }
        switch (path) {
            case "/api/scene":
                json(exchange, 200, session.summary());
                return;
            case "/api/trace":
                trace(exchange, query);
                return;
            case "/api/rerender":
                rerender(exchange);
                return;
            case "/api/image.png":
                png(exchange, session.renderPng(), session.renderError() != null ? session.renderError() : "no render");
                return;
            case "/api/reference.png":
                png(exchange, session.referencePng(), "this scene has no reference image");
                return;
            case "/api/diff.png":
                png(exchange, session.differencePng(), "no difference image: no reference, no render, or sizes differ");
                return;
            default:
                text(exchange, 404, "no such page: " + path + " (the page is /, the API under /api/)");
        }
    }

    private void trace(HttpExchange exchange, String query) throws IOException {
        Query q = Query.parse(query);
        String problem = q.problem("x", "y");
        if (problem != null) {
            text(exchange, 400, problem + "; expected /api/trace?x=X&y=Y with whole numbers, X from the left and Y from the top");
            return;
        }
        int x = q.integer("x");
        int y = q.integer("y");
        String outside = session.outOfRange(x, y);
        if (outside != null) {
            text(exchange, 400, outside);
            return;
        }
        json(exchange, 200, session.trace(x, y));
    }

    private void rerender(HttpExchange exchange) throws IOException {
        try {
            session.reload();
        } catch (SceneException e) {
            JsonObject error = new JsonObject();
            error.addProperty("error", e.getMessage());
            json(exchange, 400, error);
            return;
        }
        json(exchange, 200, session.summary());
    }

    private static boolean fromThisMachine(HttpExchange exchange) {
        String host = exchange.getRequestHeaders().getFirst("Host");
        if (host == null) {
            return true;
        }
        String name = host.toLowerCase(Locale.ROOT).replaceFirst(":\\d+$", "");
        return name.equals("127.0.0.1") || name.equals("localhost") || name.equals("[::1]");
    }

    private static void resource(HttpExchange exchange, String name, String type) throws IOException {
        try (InputStream in = ExploreServer.class.getResourceAsStream(name)) {
            if (in == null) {
                text(exchange, 500, "the page's " + name + " is missing from ray1's resources");
                return;
            }
            send(exchange, 200, type, in.readAllBytes());
        }
    }

    private static void png(HttpExchange exchange, byte[] png, String whyNone) throws IOException {
        if (png == null) {
            text(exchange, 404, whyNone);
            return;
        }
        send(exchange, 200, "image/png", png);
    }

    private static void json(HttpExchange exchange, int status, JsonObject body) throws IOException {
        send(exchange, status, "application/json; charset=utf-8", body.toString().getBytes(StandardCharsets.UTF_8));
    }

    private static void text(HttpExchange exchange, int status, String line) throws IOException {
        send(exchange, status, "text/plain; charset=utf-8", (line + "\n").getBytes(StandardCharsets.UTF_8));
    }

    private static void send(HttpExchange exchange, int status, String type, byte[] body) throws IOException {
        exchange.getResponseHeaders().set("Content-Type", type);
        exchange.getResponseHeaders().set("Cache-Control", "no-store");
        exchange.getResponseHeaders().set("X-Content-Type-Options", "nosniff");
        exchange.sendResponseHeaders(status, body.length == 0 ? -1 : body.length);
        try (OutputStream out = exchange.getResponseBody()) {
            out.write(body);
        }
    }
}
