package org.fdnet.hi.edit;

import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.runtime.ChangeOutcome;

/**
 * Asked before an edit (or an undo, or a redo) changes the editor's network. Offline there is none; while the
 * editor is attached to a running network, the gate sends the change there first, and the editor applies it
 * only when the network executed it (the thesis's Figure 37: a refused edit leaves the view untouched).
 */
@FunctionalInterface
public interface EditGate {
    /**
     * @param label  what the user did ("Delete node main/judge", "Undo Add node main/x")
     * @param before a copy of the editor's network before the change
     * @param after  a copy of the editor's network as the change makes it
     * @return executed, or failed with the reason (the editor then changes nothing)
     */
    ChangeOutcome admit(String label, NetworkInfo before, NetworkInfo after);
}
