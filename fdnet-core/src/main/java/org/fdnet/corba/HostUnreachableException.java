package org.fdnet.corba;

/** A host or the naming service could not be reached; the message names which and where. */
public final class HostUnreachableException extends RuntimeException {
    public HostUnreachableException(String message, Throwable cause) {
        super(message, cause);
    }

    public HostUnreachableException(String message) {
        super(message);
    }
}
