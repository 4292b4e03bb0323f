package org.fdnet.roq.sim;

/** A course file that cannot be read; the message reads {@code SOURCE:LINE: what is wrong}. */
public final class CourseFormatException extends Exception {
    private static final long serialVersionUID = 1L;

    CourseFormatException(String message, Throwable cause) {
        super(message, cause);
    }
}
