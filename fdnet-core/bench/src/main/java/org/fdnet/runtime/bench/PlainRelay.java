package org.fdnet.runtime.bench;

/**
 * The baseline: the same work as a {@link Relay} hop done with plain Java — a value object written to a
 * volatile field, a virtual call that adds one and publishes the result, an observer call. What is left
 * of FDNet's figures after subtracting this is the runtime's own cost.
 */
final class PlainRelay {
    /** Stands in for a Data: holds the latest value and tells one consumer. */
    static final class Cell {
        volatile Double value = 0.0;
        Consumer next;

        void set(double v) {
            value = v;
            if (next != null) {
                next.accept(v);
            }
        }
    }

    interface Consumer {
        void accept(double v);
    }

    /** A hop: cell → +1 → cell. */
    static Consumer hop(Cell out) {
        return v -> out.set(v + 1);
    }
}
