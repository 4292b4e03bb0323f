package org.fdnet.runtime.library;

import org.fdnet.event.ValueType;
import org.fdnet.runtime.Data;

/** A Data holding a boolean (e.g. a judgment: move or not). Parameter: {@code initial} (the first value; default: false). */
public class BooleanData extends Data {
    @Override
    public ValueType type() {
        return ValueType.BOOLEAN;
    }
}
