package org.fdnet.hi.live;

import java.util.Set;

/** What a {@link LiveSession} tells the window, always on the Swing thread. */
public interface LiveSessionListener {
    /** Something happened worth a line in the status bar (a change the network made, an executed command). */
    void info(String message);

    /** A command was refused or could not be sent. */
    void error(String message);

    /** Which modules run and which of them are on hold, as last read from the network. */
    void modulesChanged(Set<String> loaded, Set<String> held);

    /** The session ended: detached by the user ({@code lost} false) or the network was lost. */
    void ended(boolean lost, String reason);
}
