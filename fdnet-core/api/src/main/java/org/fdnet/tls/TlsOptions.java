package org.fdnet.tls;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code --tls FILE} and {@code --insecure}, shared by every command that listens or connects: apply them first, then
 * check each address the process listens on with {@link #requireSafeBind}.
 */
public final class TlsOptions {
    @Option(names = "--tls", paramLabel = "FILE.p12",
            description = "speak mutual TLS with this process's certificate (made by fdnet keys; the password file"
                    + " beside it); required to listen on a non-loopback address")
    Path store;

    @Option(names = "--insecure",
            description = "allow listening on a non-loopback address without TLS (only on a network you trust)")
    boolean insecure;

    /**
     * Turns TLS on for this process when {@code --tls} was given.
     *
     * @throws IllegalArgumentException when the file cannot be used
     */
    public void apply() {
        if (store != null) {
            TransportSecurity.use(TlsIdentity.load(store));
        }
    }

    /**
     * See {@link TransportSecurity#requireSafeBind}.
     *
     * @param what    the server, for the message, e.g. {@code the logger's receiver}
     * @param address the address it is to listen on
     * @throws IllegalStateException when it would listen on a non-loopback address without TLS or {@code --insecure}
     */
    public void requireSafeBind(String what, String address) {
        TransportSecurity.requireSafeBind(what, address, insecure);
    }

    /**
     * Whether {@code --tls} was given.
     *
     * @return true when this process is to speak TLS
     */
    public boolean tls() {
        return store != null;
    }
}
