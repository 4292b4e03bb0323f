package org.fdnet.runtime;

/** A node parameter is missing or does not parse; the message names the node, the parameter and the value. */
public class ParameterException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    public ParameterException(String message) {
        super(message);
    }

    public ParameterException(String message, Throwable cause) {
        super(message, cause);
    }
}
