package org.fdnet.netinfo.xml;

import java.nio.file.Path;
import java.util.List;
import org.fdnet.netinfo.NetworkInfo;

/**
 * A network as read from a file, with what {@code fdnet fmt} needs to write it back in place.
 *
 * @param doctypeSystemId the SYSTEM id of the file's DOCTYPE, or {@code null} if it had none
 * @param leadingComments the comments before the root element, kept by a rewrite
 * @param innerComments   how many comments stood inside the root element; a rewrite loses them
 */
public record NetworkDocument(Path file, NetworkInfo network, String doctypeSystemId,
                              List<String> leadingComments, int innerComments) {
    public NetworkDocument {
        leadingComments = List.copyOf(leadingComments);
    }
}
