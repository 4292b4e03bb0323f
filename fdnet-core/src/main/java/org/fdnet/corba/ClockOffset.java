package org.fdnet.corba;

import org.fdnet.corba.idl.Host;

/**
 * How far a host's clock is ahead of this process's, measured as NTP does: ask its clock several times, keep the
 * answer of the quickest round trip and assume it was read half-way through it. The error is at most half that
 * round trip (well under a millisecond between hosts on one network).
 */
final class ClockOffset {
    private static final int SAMPLES = 5;

    private ClockOffset() {
    }

    /** The host's clock minus this process's, in µs. */
    static long of(Host host) {
        long bestRoundTrip = Long.MAX_VALUE;
        long offset = 0;
        for (int i = 0; i < SAMPLES; i++) {
            long sentNanos = System.nanoTime();
            long sentMicros = System.currentTimeMillis() * 1000;
            long remote = host.clockMicros();
            long roundTrip = (System.nanoTime() - sentNanos) / 1000;
            if (roundTrip < bestRoundTrip) {
                bestRoundTrip = roundTrip;
                offset = remote - (sentMicros + roundTrip / 2);
            }
        }
        return offset;
    }
}
