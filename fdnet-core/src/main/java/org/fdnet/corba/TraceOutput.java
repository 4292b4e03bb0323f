package org.fdnet.corba;

/** Where the lines of a distributed run's {@code --trace} go ({@link TraceCollector}); called from one thread. */
public interface TraceOutput {
    /** One event of {@code host}, at {@code timeMicros} on this process's clock (the host's offset taken off). */
    void line(String host, long timeMicros, String text);

    /** {@code host} dropped {@code count} events because its trace buffer was full (this process read too slowly). */
    void dropped(String host, long count);
}
