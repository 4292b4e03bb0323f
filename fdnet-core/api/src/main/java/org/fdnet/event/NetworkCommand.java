package org.fdnet.event;

import java.util.Locale;

/** The commands of {@code netcommand_log}: the thesis's four, plus FDNet's module commands. */
public enum NetworkCommand {
    /** A node was created. */
    CREATE,
    /** A node was destroyed. */
    DESTROY,
    /** A Reader or Writer was made. */
    CONNECT,
    /** A Reader or Writer was removed. */
    DISCONNECT,
    /** A module was loaded. */
    LOAD,
    /** A module was unloaded. */
    UNLOAD,
    /** A module's Relations were put on hold. */
    HOLD,
    /** A held module's Relations were let fire again. */
    RESUME;

    /**
     * The text stored in the {@code command} column: {@code create}, {@code connect}, ...
     *
     * @return the lower-case name
     */
    public String text() {
        return name().toLowerCase(Locale.ROOT);
    }
}
