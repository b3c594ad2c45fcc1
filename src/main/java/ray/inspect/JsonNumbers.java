package ray.inspect;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonNull;
import com.google.gson.JsonPrimitive;
import ray.math.Vec3;

/** Numbers and vectors as JSON values: JSON has no NaN or infinity, so those become null. */
public final class JsonNumbers {
    private JsonNumbers() {
    }

    public static JsonElement num(double x) {
        return Double.isFinite(x) ? new JsonPrimitive(x) : JsonNull.INSTANCE;
    }

    /** [x, y, z], or null for a missing vector. */
    public static JsonElement vec(Vec3 v) {
        if (v == null) {
            return JsonNull.INSTANCE;
        }
        JsonArray a = new JsonArray();
        a.add(num(v.x));
        a.add(num(v.y));
        a.add(num(v.z));
        return a;
    }

    /** An 8-bit color as [r, g, b]. */
    public static JsonArray rgb(int[] rgb) {
        JsonArray a = new JsonArray();
        for (int c : rgb) {
            a.add(c);
        }
        return a;
    }
}
