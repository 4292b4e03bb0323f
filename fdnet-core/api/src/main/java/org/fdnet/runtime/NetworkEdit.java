package org.fdnet.runtime;

import org.fdnet.netinfo.NetworkInfo;

/**
 * One edit of a running network's definition, expressed on {@link NetworkInfo} (so every edit the
 * editor knows — add, delete, rename, replace, merge, connect — is available). The controller applies it
 * to a copy, checks that the result can run, and only then makes the running network match it; a
 * refused edit ({@link org.fdnet.netinfo.EditRefusedException}) changes nothing. See {@link NetworkEdits}.
 */
@FunctionalInterface
public interface NetworkEdit {
    /**
     * Makes the edit on {@code network}.
     *
     * @param network a copy of the running network's definition, discarded when this throws
     * @throws org.fdnet.netinfo.EditRefusedException to refuse the edit, saying why
     */
    void applyTo(NetworkInfo network);
}
