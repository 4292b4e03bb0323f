package org.fdnet.runtime.library;

import org.fdnet.event.ValueType;
import org.fdnet.runtime.Data;

/** A Data holding bytes (Base64 in files and events). Parameter: {@code initial} (the first value; default: no bytes). */
public class BytesData extends Data {
    @Override
    public ValueType type() {
        return ValueType.BYTES;
    }
}
