package org.fdnet.corba;

import java.util.Objects;

/**
 * Where a value entered the links: the stream of its first hop ({@code host#incarnation#link}) and its
 * number in that stream. It travels with the value through relays, so a host can tell a value it already
 * applied (sent again after a relay's death) from a new one.
 *
 * <p>While an inbound link injects a value, the value's origin is {@linkplain #current() current} on that
 * thread: the engine tells its observers on the writing thread, so an outbound link relaying the value
 * picks the origin up.
 */
public record ValueOrigin(String stream, long seq) {
    private static final ThreadLocal<ValueOrigin> CURRENT = new ThreadLocal<>();

    public ValueOrigin {
        Objects.requireNonNull(stream, "stream");
    }

    /** The origin of the value being injected on this thread, or {@code null} for a local write. */
    public static ValueOrigin current() {
        return CURRENT.get();
    }

    /** Runs {@code injection} with {@code origin} current. */
    static void during(ValueOrigin origin, Runnable injection) {
        ValueOrigin previous = CURRENT.get();
        CURRENT.set(origin);
        try {
            injection.run();
        } finally {
            if (previous == null) {
                CURRENT.remove();
            } else {
                CURRENT.set(previous);
            }
        }
    }
}
