package org.fdnet.netinfo.xml;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.List;
import org.fdnet.netinfo.NetworkInfo;

/**
 * Loads and saves .fdn network definitions. Loading validates against the bundled {@code cnet.dtd}
 * and the model's rules and reports every problem as {@code file:line:col: message}; saving writes
 * the canonical form (see {@link NetworkFileWriter}) atomically. For every valid file,
 * load → save → load gives an equal {@link NetworkInfo}.
 */
public final class NetworkRepository {
    /** The DOCTYPE SYSTEM id written when the network has none of its own. */
    public static final String DEFAULT_SYSTEM_ID = BundledDtd.CNET.fileName();

    private NetworkRepository() {
    }

    public static NetworkInfo load(Path file) throws NetworkFileException {
        return read(file).network();
    }

    /**
     * Reads a definition sent as text (the control object's snapshot and edits), validated as a file is; each
     * problem is reported as {@code source:line:col: message}.
     */
    public static NetworkInfo fromText(String xml, String source) throws NetworkFileException {
        return new NetworkFileReader(Path.of(source), xml.getBytes(java.nio.charset.StandardCharsets.UTF_8)).read()
                .network();
    }

    /** The canonical text of {@code network}: what {@link #fromText} reads back into an equal definition. */
    public static String toText(NetworkInfo network) {
        return new String(toBytes(network, DEFAULT_SYSTEM_ID), java.nio.charset.StandardCharsets.UTF_8);
    }

    /** Loads a file keeping what {@code fmt} needs to rewrite it in place (its DOCTYPE). */
    public static NetworkDocument read(Path file) throws NetworkFileException {
        return new NetworkFileReader(file).read();
    }

    public static void save(NetworkInfo network, Path file) throws IOException {
        save(network, file, DEFAULT_SYSTEM_ID);
    }

    /** Writes to a temporary file beside {@code file}, then moves it over: a crash never leaves half a network. */
    public static void save(NetworkInfo network, Path file, String doctypeSystemId) throws IOException {
        save(network, file, doctypeSystemId, List.of());
    }

    /** Saves keeping a file's DOCTYPE and header comments: what {@code fdnet fmt} writes. */
    public static void save(NetworkInfo network, Path file, String doctypeSystemId, List<String> leadingComments)
            throws IOException {
        AtomicFile.write(file, out -> write(network, out, doctypeSystemId, leadingComments));
    }

    public static void write(NetworkInfo network, OutputStream out, String doctypeSystemId,
                             List<String> leadingComments) throws IOException {
        new NetworkFileWriter(network).write(out, doctypeSystemId == null ? DEFAULT_SYSTEM_ID : doctypeSystemId,
                leadingComments);
    }

    /** The canonical bytes of {@code network}, as {@link #save} would write them. */
    public static byte[] toBytes(NetworkInfo network, String doctypeSystemId) {
        return toBytes(network, doctypeSystemId, List.of());
    }

    public static byte[] toBytes(NetworkInfo network, String doctypeSystemId, List<String> leadingComments) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            write(network, out, doctypeSystemId, leadingComments);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toByteArray();
    }
}
