package org.fdnet.event;

import java.util.Locale;

/** The commands of {@code netcommand_log}: the thesis's four, plus FDNet's module commands. */
public enum NetworkCommand {
    CREATE, DESTROY, CONNECT, DISCONNECT, LOAD, UNLOAD, HOLD, RESUME;

    /** The text stored in the {@code command} column: {@code create}, {@code connect}, ... */
    public String text() {
        return name().toLowerCase(Locale.ROOT);
    }
}
