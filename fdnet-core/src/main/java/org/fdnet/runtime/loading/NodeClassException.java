package org.fdnet.runtime.loading;

/**
 * A node's class cannot be used: unknown, of the wrong kind, outside the allowed places, or failing to
 * construct. The message names module, node and class, and says what to do.
 */
public class NodeClassException extends Exception {
    private static final long serialVersionUID = 1L;

    public NodeClassException(String message) {
        super(message);
    }

    public NodeClassException(String message, Throwable cause) {
        super(message, cause);
    }
}
