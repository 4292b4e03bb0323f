package org.fdnet.runtime.cli;

import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * One {@code --set MODULE/NODE=VALUE} of {@code fdnet run}, single or distributed: a Data and the text of
 * its value (a bare node name means module main).
 */
public record ValueAssignment(NodeRef data, String value) {
    /** @throws IllegalArgumentException with the message to print after {@code --set TEXT: } */
    public static ValueAssignment parse(String text) {
        int eq = text.indexOf('=');
        if (eq < 0) {
            throw new IllegalArgumentException("expected MODULE/NODE=VALUE");
        }
        return new ValueAssignment(NodeRef.parse(text.substring(0, eq).strip(), ModuleInfo.MAIN), text.substring(eq + 1));
    }
}
