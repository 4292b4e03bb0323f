package org.fdnet.corba;

/** A distributed network could not be set up; the message names the host, node or link and why. */
public final class DeploymentException extends Exception {
    public DeploymentException(String message) {
        super(message);
    }

    public DeploymentException(String message, Throwable cause) {
        super(message, cause);
    }
}
