package org.fdnet.hi.text;

import org.fdnet.netinfo.NetworkChange;

/** A module frame follows its module when it is renamed, here or elsewhere (the graphic editor, undo). */
final class ModuleRenames {
    private ModuleRenames() {
    }

    /** The module's name after {@code change}: the new name when the change renamed it, else unchanged. */
    static String follow(String module, NetworkChange change) {
        if (change.kind() == NetworkChange.Kind.MODULE_RENAMED && module.equals(change.subject())) {
            return change.module();
        }
        return module;
    }
}
