package org.fdnet.runtime;

/** A message no servant answered: no servant at that path, or the servant refused it. The message says why. */
public final class MessageRefusedException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public MessageRefusedException(String reason) {
        super(reason);
    }
}
