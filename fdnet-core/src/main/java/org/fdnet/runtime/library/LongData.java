package org.fdnet.runtime.library;

import org.fdnet.event.ValueType;
import org.fdnet.runtime.Data;

/** A Data holding a whole number (counters, modes, indexes). Parameter: {@code initial} (the first value; default: 0). */
public class LongData extends Data {
    @Override
    public ValueType type() {
        return ValueType.LONG;
    }
}
