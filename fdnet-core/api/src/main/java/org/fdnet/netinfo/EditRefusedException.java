package org.fdnet.netinfo;

/**
 * An edit that would break the model. The model is left exactly as it was; the message says why in
 * words a user understands ("module 'Arm' already has a node named 'Shoulder'").
 */
public class EditRefusedException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /**
     * A refusal.
     *
     * @param message why, naming the module, node or connection, as a user reads it
     */
    public EditRefusedException(String message) {
        super(message);
    }
}
