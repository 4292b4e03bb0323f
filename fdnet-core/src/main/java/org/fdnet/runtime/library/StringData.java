package org.fdnet.runtime.library;

import org.fdnet.event.ValueType;
import org.fdnet.runtime.Data;

/** A Data holding a text (a mode name, a message). Parameter: {@code initial} (the first value; default: empty). */
public class StringData extends Data {
    @Override
    public ValueType type() {
        return ValueType.STRING;
    }
}
