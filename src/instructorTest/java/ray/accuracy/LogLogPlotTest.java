package ray.accuracy;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.fail;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Collections;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

public class LogLogPlotTest {
    private static Document parse(String svg) throws Exception {
        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        factory.setNamespaceAware(true);
        return factory.newDocumentBuilder().parse(new ByteArrayInputStream(svg.getBytes(StandardCharsets.UTF_8)));
    }

    private static double attr(Element e, String name) {
        return Double.parseDouble(e.getAttribute(name));
    }

    @Test
    public void pointsLandOnTheirDecadesAndLabelsAreEscaped() throws Exception {
        // x spans decades 0..2 over pixels 70..620, y spans −2..0 over pixels 370..36 (up is smaller).
        String svg = new LogLogPlot("error vs time", "seconds", "RMSE")
                .points("runs", "#c00", Arrays.asList(new LogLogPlot.Point(1, 1, "a<b & c"),
                        new LogLogPlot.Point(10, 0.1, null), new LogLogPlot.Point(100, 0.01, "64 spp")))
                .line("Pareto front", "#06c", false, Arrays.asList(new LogLogPlot.Point(1, 1, null), new LogLogPlot.Point(100, 0.01, null)))
                .line("slope −½", "#999", true, Collections.singletonList(new LogLogPlot.Point(10, 0.5, null)))
                .toSvg();
        Document doc = parse(svg);
        NodeList circles = doc.getElementsByTagName("circle");
        assertEquals("three data points and one legend dot", 4, circles.getLength());
        double[][] expected = {{70, 36}, {345, 203}, {620, 370}};
        for (int k = 0; k < 3; k++) {
            Element c = (Element) circles.item(k);
            assertEquals("cx of point " + k, expected[k][0], attr(c, "cx"), 0.05);
            assertEquals("cy of point " + k, expected[k][1], attr(c, "cy"), 0.05);
        }
        Element front = (Element) doc.getElementsByTagName("polyline").item(0);
        assertEquals("70.0,36.0 620.0,370.0", front.getAttribute("points"));
        Element ideal = (Element) doc.getElementsByTagName("polyline").item(1);
        assertEquals("6 4", ideal.getAttribute("stroke-dasharray"));
        NodeList texts = doc.getElementsByTagName("text");
        boolean escapedLabel = false;
        for (int k = 0; k < texts.getLength(); k++) {
            escapedLabel |= texts.item(k).getTextContent().equals("a<b & c");
        }
        assertEquals("the label survives escaping", true, escapedLabel);
        // Grid: 3 vertical and 3 horizontal lines, plus one legend line per line series (2).
        assertEquals(8, doc.getElementsByTagName("line").getLength());
    }

    @Test
    public void decadesAreWrittenAsReadersExpect() {
        assertEquals("1", LogLogPlot.decade(0));
        assertEquals("1000", LogLogPlot.decade(3));
        assertEquals("10000", LogLogPlot.decade(4));
        assertEquals("1e5", LogLogPlot.decade(5));
        assertEquals("0.1", LogLogPlot.decade(-1));
        assertEquals("0.001", LogLogPlot.decade(-3));
        assertEquals("1e-4", LogLogPlot.decade(-4));
    }

    @Test
    public void valuesALogAxisCannotShowAreRefused() {
        try {
            new LogLogPlot.Point(0, 1, null);
            fail("expected an exception");
        } catch (IllegalArgumentException e) {
            assertEquals("a log-log plot needs positive finite values, got (0.0, 1.0)", e.getMessage());
        }
        try {
            new LogLogPlot("t", "x", "y").toSvg();
            fail("expected an exception");
        } catch (IllegalStateException e) {
            assertEquals("a plot needs at least one point", e.getMessage());
        }
    }

    @Test
    public void aSingleDecadeStillGetsAWholeDecadeOfAxis() {
        LogLogPlot.Axis axis = LogLogPlot.Axis.around(new double[] {10, 10}, 0, 100);
        assertEquals(1, axis.lowDecade);
        assertEquals(2, axis.highDecade);
        assertEquals(0, axis.toPixel(10), 0);
        assertEquals(50, axis.toPixel(Math.sqrt(1000)), 1e-9);
    }
}
