package org.fdnet.runtime;

/** A message no servant answered: no servant at that path, or the servant refused it. The message says why. */
public final class MessageRefusedException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /**
     * A refusal.
     *
     * @param reason why no servant answered, naming the path or the servant, shown to the sender as is
     */
    public MessageRefusedException(String reason) {
        super(reason);
    }
}
