package org.fdnet.control;

/**
 * A running network that cannot be reached any more (its process stopped, the connection broke): thrown by a
 * {@link LiveNetwork}'s queries ({@code snapshot}, {@code loadedModules}); its changes are refused with the same
 * message instead. The message names the network and its address.
 */
public class NetworkUnreachableException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public NetworkUnreachableException(String message) {
        super(message);
    }

    public NetworkUnreachableException(String message, Throwable cause) {
        super(message, cause);
    }
}
