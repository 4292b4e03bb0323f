package org.fdnet.roq.sim;

/**
 * roq-sim's native library cannot be used: it is missing, cannot be linked, or was built for another ABI. The
 * message names the missing piece (gcc, libmujoco-dev, the build) and the one command that fixes it.
 */
public final class NativeLibraryUnavailableException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    NativeLibraryUnavailableException(String message, Throwable cause) {
        super(message, cause);
    }
}
