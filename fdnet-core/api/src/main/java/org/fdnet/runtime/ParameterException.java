package org.fdnet.runtime;

/**
 * A node's parameter is missing, does not parse, lies outside its declared range, or does not fit with another: the
 * message names module, node, parameter and what is allowed, e.g. {@code module 'Walk', node 'gait': parameter
 * 'stride' must be a number in [0, 0.3] m, was 0.5}. Thrown from {@code init} (or by the engine's check before it),
 * it keeps the node from starting and the network as it was.
 */
public class ParameterException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    /**
     * A refusal.
     *
     * @param message the whole message, naming module, node and parameter
     */
    public ParameterException(String message) {
        super(message);
    }

    /**
     * A refusal caused by a parser's.
     *
     * @param message the whole message, naming module, node and parameter
     * @param cause   what the parser refused
     */
    public ParameterException(String message, Throwable cause) {
        super(message, cause);
    }
}
