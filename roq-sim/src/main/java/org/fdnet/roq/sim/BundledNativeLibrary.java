package org.fdnet.roq.sim;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.Optional;

/**
 * The copy of {@code libroqsim.so} that roq-sim's jar carries (the build puts it at {@value #RESOURCE}), for a
 * user's project that depends on the installed artifact: the JVM cannot load a library from inside a jar, so it is
 * written once to a cache folder named by its content's SHA-256 and loaded from there. Two processes, or two
 * versions of roq-sim, never overwrite each other's file: each writes a temporary file and moves it into place.
 *
 * <p>The cache folder is {@code $XDG_CACHE_HOME/fdnet/native} (or {@code ~/.cache/fdnet/native}), or the system
 * property {@value #CACHE_PROPERTY}.
 */
final class BundledNativeLibrary {
    /** Where the jar holds the library. */
    static final String RESOURCE = "/org/fdnet/roq/sim/native/" + RoqNativeLibrary.LIBRARY_FILE;
    /** System property naming the folder the library is extracted to. */
    static final String CACHE_PROPERTY = "fdnet.native.cache";

    private BundledNativeLibrary() {
    }

    /** The library extracted from the jar's copy, or empty when the class path carries none. */
    static Optional<Path> extracted() {
        byte[] bytes;
        try (InputStream in = BundledNativeLibrary.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                return Optional.empty();
            }
            bytes = in.readAllBytes();
        } catch (IOException e) {
            throw new UncheckedIOException("roq-sim: cannot read its bundled " + RESOURCE, e);
        }
        Path folder = cacheFolder().resolve(sha256(bytes).substring(0, 16));
        Path library = folder.resolve(RoqNativeLibrary.LIBRARY_FILE);
        try {
            if (!Files.isRegularFile(library) || Files.size(library) != bytes.length) {
                Files.createDirectories(folder);
                Path partial = Files.createTempFile(folder, "libroqsim", ".part");
                Files.write(partial, bytes);
                Files.move(partial, library, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            }
        } catch (IOException e) {
            throw new NativeLibraryUnavailableException("roq-sim: cannot write its native library to " + folder
                    + " (" + e.getMessage() + "); set -D" + CACHE_PROPERTY + "=A_WRITABLE_FOLDER", e);
        }
        return Optional.of(library);
    }

    private static Path cacheFolder() {
        String property = System.getProperty(CACHE_PROPERTY);
        if (property != null && !property.isBlank()) {
            return Path.of(property);
        }
        String xdg = System.getenv("XDG_CACHE_HOME");
        Path base = xdg != null && !xdg.isBlank() ? Path.of(xdg) : Path.of(System.getProperty("user.home"), ".cache");
        return base.resolve("fdnet").resolve("native");
    }

    private static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every JVM has SHA-256", e);
        }
    }
}
