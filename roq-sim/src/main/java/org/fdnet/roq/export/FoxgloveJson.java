package org.fdnet.roq.export;

/**
 * JSON of Foxglove's well-known message types (https://docs.foxglove.dev/docs/visualization/message-schemas), written
 * with every field a decoder may look for, and the JSON Schemas the export declares for them.
 */
final class FoxgloveJson {
    static final String FRAME_TRANSFORM = "foxglove.FrameTransform";
    static final String SCENE_UPDATE = "foxglove.SceneUpdate";

    private FoxgloveJson() {
    }

    static String time(long nanos) {
        return "{\"sec\":" + Math.floorDiv(nanos, 1_000_000_000L) + ",\"nsec\":" + Math.floorMod(nanos, 1_000_000_000L) + "}";
    }

    /** A number rounded to 10 µm (or 1e-6 of a unit quaternion): short JSON, no formatter (it costs per frame). */
    static String number(double v) {
        return Double.toString(Math.rint(v * 1e6) / 1e6);
    }

    static String vector(double x, double y, double z) {
        return "{\"x\":" + number(x) + ",\"y\":" + number(y) + ",\"z\":" + number(z) + "}";
    }

    static String quaternion(double[] q) {
        return "{\"x\":" + number(q[0]) + ",\"y\":" + number(q[1]) + ",\"z\":" + number(q[2]) + ",\"w\":" + number(q[3]) + "}";
    }

    /** The rotation roll about x, then pitch about y, then yaw about z, as {x, y, z, w}. */
    static double[] rotation(double roll, double pitch, double yaw) {
        double cr = Math.cos(roll / 2);
        double sr = Math.sin(roll / 2);
        double cp = Math.cos(pitch / 2);
        double sp = Math.sin(pitch / 2);
        double cy = Math.cos(yaw / 2);
        double sy = Math.sin(yaw / 2);
        return new double[] {sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy,
                cr * cp * cy + sr * sp * sy};
    }

    static String pose(double x, double y, double z, double[] q) {
        return "{\"position\":" + vector(x, y, z) + ",\"orientation\":" + quaternion(q) + "}";
    }

    static String color(int rgb, double alpha) {
        return "{\"r\":" + number(((rgb >> 16) & 0xFF) / 255.0) + ",\"g\":" + number(((rgb >> 8) & 0xFF) / 255.0)
                + ",\"b\":" + number((rgb & 0xFF) / 255.0) + ",\"a\":" + number(alpha) + "}";
    }

    static String frameTransform(long nanos, String parent, String child, double x, double y, double z, double[] q) {
        return "{\"timestamp\":" + time(nanos) + ",\"parent_frame_id\":\"" + parent + "\",\"child_frame_id\":\"" + child
                + "\",\"translation\":" + vector(x, y, z) + ",\"rotation\":" + quaternion(q) + "}";
    }

    /** One entity of a scene update, every primitive list given (empty ones as []). */
    static String entity(long nanos, String frame, String id, String arrows, String cubes, String spheres, String lines) {
        return "{\"timestamp\":" + time(nanos) + ",\"frame_id\":\"" + frame + "\",\"id\":\"" + id
                + "\",\"lifetime\":{\"sec\":0,\"nsec\":0},\"frame_locked\":true,\"metadata\":[],\"arrows\":[" + arrows
                + "],\"cubes\":[" + cubes + "],\"spheres\":[" + spheres + "],\"cylinders\":[],\"lines\":[" + lines
                + "],\"triangles\":[],\"texts\":[],\"models\":[]}";
    }

    static String sceneUpdate(String... entities) {
        return "{\"deletions\":[],\"entities\":[" + String.join(",", entities) + "]}";
    }

    static String cube(String pose, double sx, double sy, double sz, String color) {
        return "{\"pose\":" + pose + ",\"size\":" + vector(sx, sy, sz) + ",\"color\":" + color + "}";
    }

    static String sphere(String pose, double diameter, String color) {
        return "{\"pose\":" + pose + ",\"size\":" + vector(diameter, diameter, diameter) + ",\"color\":" + color + "}";
    }

    /** An arrow from {@code pose} along its x axis. */
    static String arrow(String pose, double length, String color) {
        double head = Math.min(0.04, length / 3);
        return "{\"pose\":" + pose + ",\"shaft_length\":" + number(Math.max(0, length - head))
                + ",\"shaft_diameter\":0.012,\"head_length\":" + number(head) + ",\"head_diameter\":0.03,\"color\":" + color + "}";
    }

    /** A line strip (type 0) through {@code points} ({x, y, z} in turn). */
    static String lineStrip(double[] points, double thickness, String color) {
        StringBuilder p = new StringBuilder();
        for (int i = 0; i < points.length; i += 3) {
            p.append(i > 0 ? "," : "").append(vector(points[i], points[i + 1], points[i + 2]));
        }
        return "{\"type\":0,\"pose\":" + pose(0, 0, 0, IDENTITY) + ",\"thickness\":" + number(thickness)
                + ",\"scale_invariant\":false,\"points\":[" + p + "],\"color\":" + color + ",\"colors\":[],\"indices\":[]}";
    }

    static final double[] IDENTITY = {0, 0, 0, 1};

    private static final String TIME = "{\"type\":\"object\",\"properties\":{\"sec\":{\"type\":\"integer\",\"minimum\":0},"
            + "\"nsec\":{\"type\":\"integer\",\"minimum\":0,\"maximum\":999999999}}}";
    private static final String VECTOR = "{\"type\":\"object\",\"properties\":{\"x\":{\"type\":\"number\"},"
            + "\"y\":{\"type\":\"number\"},\"z\":{\"type\":\"number\"}}}";
    private static final String QUATERNION = "{\"type\":\"object\",\"properties\":{\"x\":{\"type\":\"number\"},"
            + "\"y\":{\"type\":\"number\"},\"z\":{\"type\":\"number\"},\"w\":{\"type\":\"number\"}}}";
    private static final String POSE = "{\"type\":\"object\",\"properties\":{\"position\":" + VECTOR + ",\"orientation\":"
            + QUATERNION + "}}";
    private static final String COLOR = "{\"type\":\"object\",\"properties\":{\"r\":{\"type\":\"number\"},"
            + "\"g\":{\"type\":\"number\"},\"b\":{\"type\":\"number\"},\"a\":{\"type\":\"number\"}}}";

    /** foxglove.FrameTransform's fields, as a JSON Schema. */
    static String frameTransformSchema() {
        return "{\"title\":\"" + FRAME_TRANSFORM + "\",\"description\":\"A transform between two reference frames in 3D space\","
                + "\"type\":\"object\",\"properties\":{\"timestamp\":" + TIME + ",\"parent_frame_id\":{\"type\":\"string\"},"
                + "\"child_frame_id\":{\"type\":\"string\"},\"translation\":" + VECTOR + ",\"rotation\":" + QUATERNION + "}}";
    }

    /** foxglove.SceneUpdate's fields (the primitives drawn here in detail), as a JSON Schema. */
    static String sceneUpdateSchema() {
        String shape = "{\"type\":\"object\",\"properties\":{\"pose\":" + POSE + ",\"size\":" + VECTOR + ",\"color\":" + COLOR + "}}";
        String arrow = "{\"type\":\"object\",\"properties\":{\"pose\":" + POSE + ",\"shaft_length\":{\"type\":\"number\"},"
                + "\"shaft_diameter\":{\"type\":\"number\"},\"head_length\":{\"type\":\"number\"},"
                + "\"head_diameter\":{\"type\":\"number\"},\"color\":" + COLOR + "}}";
        String line = "{\"type\":\"object\",\"properties\":{\"type\":{\"type\":\"integer\",\"enum\":[0,1,2]},\"pose\":" + POSE
                + ",\"thickness\":{\"type\":\"number\"},\"scale_invariant\":{\"type\":\"boolean\"},\"points\":{\"type\":"
                + "\"array\",\"items\":" + VECTOR + "},\"color\":" + COLOR + ",\"colors\":{\"type\":\"array\"},"
                + "\"indices\":{\"type\":\"array\",\"items\":{\"type\":\"integer\"}}}}";
        String entity = "{\"type\":\"object\",\"properties\":{\"timestamp\":" + TIME + ",\"frame_id\":{\"type\":\"string\"},"
                + "\"id\":{\"type\":\"string\"},\"lifetime\":" + TIME + ",\"frame_locked\":{\"type\":\"boolean\"},"
                + "\"metadata\":{\"type\":\"array\"},\"arrows\":{\"type\":\"array\",\"items\":" + arrow + "},"
                + "\"cubes\":{\"type\":\"array\",\"items\":" + shape + "},\"spheres\":{\"type\":\"array\",\"items\":" + shape
                + "},\"cylinders\":{\"type\":\"array\"},\"lines\":{\"type\":\"array\",\"items\":" + line + "},"
                + "\"triangles\":{\"type\":\"array\"},\"texts\":{\"type\":\"array\"},\"models\":{\"type\":\"array\"}}}";
        return "{\"title\":\"" + SCENE_UPDATE + "\",\"description\":\"An update to the entities displayed in a 3D scene\","
                + "\"type\":\"object\",\"properties\":{\"deletions\":{\"type\":\"array\"},\"entities\":{\"type\":\"array\","
                + "\"items\":" + entity + "}}}";
    }
}
