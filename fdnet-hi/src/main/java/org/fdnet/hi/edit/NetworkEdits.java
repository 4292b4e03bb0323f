package org.fdnet.hi.edit;

import org.fdnet.netinfo.ModelRules;

/** The edits of the network as a whole and their inverses. */
final class NetworkEdits {
    private NetworkEdits() {
    }

    /**
     * The network's own name (the thesis's Network frame), checked like a module's name; inverse: the old name
     * back (a network read without a name gets one; undo gives it back nameless).
     */
    static ReversibleEdit rename(String to) {
        return target -> {
            ModelRules.checkName("network", to);
            String from = target.network().name();
            target.network().setName(to);
            return from == null ? t -> {
                t.network().setName(null);
                return rename(to);
            } : rename(from);
        };
    }
}
