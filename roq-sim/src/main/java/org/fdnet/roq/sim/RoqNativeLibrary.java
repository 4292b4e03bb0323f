package org.fdnet.roq.sim;

import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.List;

/**
 * Loads {@code libroqsim.so} once per JVM and checks the ABI handshake: layout version and block size, then every
 * shared figure by name ({@link LayoutHandshake}). When something is missing it says which piece and the one
 * command that installs it.
 *
 * <p>Where the library is looked for: the system property {@value #LIBRARY_PROPERTY}; else {@code native/} beside
 * the directory or jar roq-sim's classes come from (the Maven build puts it in {@code roq-sim/target/native}); else
 * the copy inside roq-sim's jar ({@link BundledNativeLibrary}), which is how a project that depends on the installed
 * artifact gets it.
 */
public final class RoqNativeLibrary {
    /** System property naming the library file. */
    public static final String LIBRARY_PROPERTY = "fdnet.roq.library";
    /** The library's file name. */
    public static final String LIBRARY_FILE = "libroqsim.so";
    /** The one command that installs what the native build and run need (Debian). */
    public static final String INSTALL_COMMAND = "apt-get install -y gcc libmujoco-dev";
    /** Where Debian's libmujoco-dev puts MuJoCo's header. */
    static final Path MUJOCO_HEADER = Path.of("/usr/include/mujoco/mujoco.h");

    private static Path loaded;

    private RoqNativeLibrary() {
    }

    /** Loads the library from its default place (see the class comment) unless already loaded. */
    public static synchronized void ensureLoaded() {
        ensureLoaded(defaultPath());
    }

    /**
     * Loads the library from {@code library} unless one is already loaded and checks the handshake.
     *
     * @throws NativeLibraryUnavailableException naming the missing piece and the command that fixes it
     */
    public static synchronized void ensureLoaded(Path library) {
        if (!Files.isRegularFile(library)) {
            throw new NativeLibraryUnavailableException(missingMessage(library), null);
        }
        if (loaded == null) {
            try {
                System.load(library.toAbsolutePath().toString());
            } catch (UnsatisfiedLinkError e) {
                throw new NativeLibraryUnavailableException("roq-sim: cannot link " + library + ": " + e.getMessage()
                        + (e.getMessage() != null && e.getMessage().contains("mujoco")
                        ? "; MuJoCo's shared library (Debian libmujoco-dev) is missing: " + INSTALL_COMMAND : ""), e);
            }
            loaded = library;
        }
        int abi;
        int size;
        String[] names;
        long[] values;
        try {
            abi = RoqNative.abiVersion();
            size = RoqNative.blockSize();
            names = RoqNative.layoutNames();
            values = RoqNative.layoutValues();
        } catch (UnsatisfiedLinkError e) {
            throw new NativeLibraryUnavailableException("roq-sim: " + loaded + " lacks the JNI entry points of this "
                    + "roq-sim (an old or foreign build); rebuild: mvn -B -pl roq-sim -am -DskipTests package", e);
        }
        if (abi != SharedBlockLayout.VERSION || size != SharedBlockLayout.BLOCK_SIZE) {
            throw new NativeLibraryUnavailableException("roq-sim: " + loaded + " was built for layout version " + abi
                    + " (block " + size + " bytes), this roq-sim needs version " + SharedBlockLayout.VERSION + " ("
                    + SharedBlockLayout.BLOCK_SIZE + " bytes); rebuild: mvn -B -pl roq-sim -am -DskipTests package", null);
        }
        List<String> moved = LayoutHandshake.mismatches(names, values);
        if (!moved.isEmpty()) {
            throw new NativeLibraryUnavailableException("roq-sim: " + loaded + " and this roq-sim disagree on the shared "
                    + "layout (" + String.join("; ", moved) + "): the ROQ_LAYOUT table of roq_layout.h and "
                    + "SharedBlockLayout.java / NativeParameters.java must change a field together; rebuild: "
                    + "mvn -B -pl roq-sim -am -DskipTests package", null);
        }
    }

    /** The library loaded in this JVM, or null. */
    public static synchronized Path loadedLibrary() {
        return loaded;
    }

    /** Where {@link #ensureLoaded()} looks. */
    public static Path defaultPath() {
        String property = System.getProperty(LIBRARY_PROPERTY);
        if (property != null && !property.isBlank()) {
            return Path.of(property);
        }
        Path beside = besideTheClasses();
        if (Files.isRegularFile(beside)) {
            return beside;
        }
        return BundledNativeLibrary.extracted().orElse(beside);
    }

    private static Path besideTheClasses() {
        CodeSource source = RoqNativeLibrary.class.getProtectionDomain().getCodeSource();
        if (source != null) {
            try {
                Path classes = Path.of(source.getLocation().toURI());
                return classes.toAbsolutePath().getParent().resolve("native").resolve(LIBRARY_FILE);
            } catch (URISyntaxException | IllegalArgumentException e) {
                throw new NativeLibraryUnavailableException("roq-sim: cannot tell where its classes come from ("
                        + source.getLocation() + "); set -D" + LIBRARY_PROPERTY + "=/path/to/" + LIBRARY_FILE, e);
            }
        }
        return Path.of(System.getProperty("fdnet.home", "."), "roq-sim", "target", "native", LIBRARY_FILE);
    }

    /** Why {@code library} is missing: which build prerequisite is absent, and the command. */
    static String missingMessage(Path library) {
        return missingMessage(library, onPath("gcc"), Files.isRegularFile(MUJOCO_HEADER));
    }

    static String missingMessage(Path library, boolean gcc, boolean mujoco) {
        StringBuilder m = new StringBuilder("roq-sim: the native library " + library + " is missing");
        if (!gcc || !mujoco) {
            m.append("; the build needs ");
            if (!gcc) {
                m.append("gcc (not on the PATH)");
            }
            if (!gcc && !mujoco) {
                m.append(" and ");
            }
            if (!mujoco) {
                m.append("libmujoco-dev (no ").append(MUJOCO_HEADER).append(")");
            }
            m.append(": ").append(INSTALL_COMMAND).append(", then mvn -B -pl roq-sim -am -DskipTests package");
        } else {
            m.append("; gcc and libmujoco-dev are present, so build it: mvn -B -pl roq-sim -am -DskipTests package");
        }
        return m.toString();
    }

    private static boolean onPath(String command) {
        String path = System.getenv("PATH");
        if (path == null) {
            return false;
        }
        for (String dir : path.split(java.io.File.pathSeparator)) {
            if (!dir.isEmpty() && Files.isExecutable(Path.of(dir, command))) {
                return true;
            }
        }
        return false;
    }
}
