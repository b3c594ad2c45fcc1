package ray.inspect;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import javax.imageio.ImageIO;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.openqa.selenium.By;
import org.openqa.selenium.JavascriptExecutor;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.TakesScreenshot;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.chrome.ChromeDriverService;
import org.openqa.selenium.chrome.ChromeOptions;
import org.openqa.selenium.interactions.Actions;
import org.openqa.selenium.support.ui.Select;
import org.openqa.selenium.support.ui.WebDriverWait;

/**
 * The explore page in a real browser (Debian's headless Chromium through its chromedriver and
 * Selenium): it loads the render, a click on a pixel shows that pixel's story with the PNG's
 * value, the zoom scales the pixels, and a click on the difference image traces the same pixel
 * grid. Leaves a screenshot in build/reports/explore/ to look at.
 */
public class ExploreBrowserTest {
    private static final String CHROMIUM = "/usr/bin/chromium";
    private static final String CHROMEDRIVER = "/usr/bin/chromedriver";
    private static final Duration WAIT = Duration.ofSeconds(60);

    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static WebDriver browser;

    @BeforeClass
    public static void startBrowser() throws Exception {
        assertTrue("the browser test needs Debian's Chromium and its driver: apt-get install -y chromium chromium-driver"
                + " (.ci/run installs them)", new File(CHROMIUM).canExecute() && new File(CHROMEDRIVER).canExecute());
        ChromeOptions options = new ChromeOptions();
        options.setBinary(CHROMIUM);
        // Headless, and without the background services that try to reach the network at start.
        options.addArguments("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync", "--window-size=1280,900",
                "--user-data-dir=" + FOLDER.newFolder("profile"));
        ChromeDriverService service = new ChromeDriverService.Builder().usingDriverExecutable(new File(CHROMEDRIVER))
                .usingAnyFreePort().build();
        browser = new ChromeDriver(service, options);
    }

    @AfterClass
    public static void stopBrowser() {
        if (browser != null) {
            browser.quit();
        }
    }

    @Test(timeout = 300_000)
    public void clickingAPixelShowsItsStory() throws Exception {
        Path out = FOLDER.newFolder("render").toPath();
        assertEquals(0, ray.cli.Ray1Command.run(new java.io.PrintWriter(new java.io.StringWriter()),
                new java.io.PrintWriter(new java.io.StringWriter()), "render", "-o", out.toString(), "scenes/one-sphere.xml"));
        BufferedImage png = ImageIO.read(out.resolve("one-sphere.png").toFile());
        try (Explorer explorer = Explorer.start(Path.of("scenes/one-sphere.xml"), null, 0)) {
            browser.get(explorer.url());
            WebElement render = waitForImage("render");
            waitForImage("reference");
            WebElement diff = waitForImage("diff");
            int zoom = Integer.parseInt(new Select(browser.findElement(By.id("zoom"))).getFirstSelectedOption().getAttribute("value"));
            assertEquals("the render is drawn at the zoom", 300 * zoom, render.getSize().getWidth());

            clickPixel(render, 150, 149, zoom);
            assertStory(png, 150, 149);
            String story = browser.findElement(By.id("trace")).getText();
            assertTrue(story, story.contains("#1 Sphere center (0, 0, 0), radius 1"));
            assertTrue("the drawing shows the camera ray", !browser.findElements(By.cssSelector("#view-top .camera-ray")).isEmpty());
            assertTrue("and the hit", !browser.findElements(By.cssSelector("#view-side .hit-point")).isEmpty());
            Path shots = Path.of("build/reports/explore");
            Files.createDirectories(shots);
            Files.write(shots.resolve("one-sphere-150-149.png"), ((TakesScreenshot) browser).getScreenshotAs(OutputType.BYTES));

            // The same pixel grid on the difference image, at another zoom. (A click lands on whole CSS
            // pixels from an element's center, which may sit between them: at 1× that can pick a neighbor.)
            new Select(browser.findElement(By.id("zoom"))).selectByValue("3");
            new WebDriverWait(browser, WAIT).until(d -> render.getSize().getWidth() == 900);
            clickPixel(diff, 60, 140, 3);
            assertStory(png, 60, 140);
        }
    }

    private static String text(String id) {
        return browser.findElement(By.id(id)).getText();
    }

    private static WebElement waitForImage(String id) {
        return new WebDriverWait(browser, WAIT).until(d -> {
            WebElement image = d.findElement(By.id(id));
            Object width = ((JavascriptExecutor) d).executeScript("return arguments[0].complete && arguments[0].naturalWidth", image);
            return width instanceof Number && ((Number) width).intValue() > 0 ? image : null;
        });
    }

    /**
     * Clicks the center of pixel (x, y) of an image drawn at {@code zoom}, as a user's pointer would:
     * the pixel scrolled to the middle of the window (clear of the page's sticky header), then a click
     * at its place in the window. A click lands on whole CSS pixels, so at 1× a fractional image edge
     * could pick a neighbor: the test clicks at 2× and more.
     */
    @SuppressWarnings("unchecked")
    private static void clickPixel(WebElement image, int x, int y, int zoom) {
        JavascriptExecutor js = (JavascriptExecutor) browser;
        js.executeScript("const r = arguments[0].getBoundingClientRect();"
                + " window.scrollBy(0, r.top + arguments[1] - window.innerHeight / 2);", image, (y + 0.5) * zoom);
        java.util.List<Number> corner = (java.util.List<Number>) js.executeScript(
                "const r = arguments[0].getBoundingClientRect(); return [r.left, r.top];", image);
        int cx = (int) Math.floor(corner.get(0).doubleValue() + (x + 0.5) * zoom);
        int cy = (int) Math.floor(corner.get(1).doubleValue() + (y + 0.5) * zoom);
        new Actions(browser).moveToLocation(cx, cy).click().perform();
    }

    private static void assertStory(BufferedImage png, int x, int y) {
        String pixel = "x = " + x + ", y = " + y;
        new WebDriverWait(browser, WAIT).withMessage(() -> "the trace panel shows \"" + text("trace-pixel") + "\", not \"" + pixel
                + "\"; status: " + text("status")).until(d -> pixel.equals(text("trace-pixel")));
        int rgb = png.getRGB(x, y);
        String value = (rgb >> 16 & 255) + ", " + (rgb >> 8 & 255) + ", " + (rgb & 255);
        new WebDriverWait(browser, WAIT).withMessage(() -> "the value shown is \"" + text("trace-value") + "\", not \"" + value + "\"")
                .until(d -> value.equals(text("trace-value")));
        assertEquals(pixel + ": the reference's value", value, browser.findElement(By.id("trace-reference")).getText());
    }
}
