package org.fdnet.corba;

import java.util.Objects;

/**
 * Where a value entered the links: the stream of its first hop ({@code host#incarnation#link}) and its
 * number in that stream. It travels with the value through relays, so a host can tell a value it already
 * applied (sent again after a relay's death) from a new one.
 *
 * <p>An inbound link {@linkplain LocalNetwork#inject injects} a value with its origin; the Data's observers
 * are told it with that value (and only that value), so an outbound link relaying the value passes the
 * origin on, while what a Relation computes from it leaves with this host's own stream.
 */
public record ValueOrigin(String stream, long seq) {
    public ValueOrigin {
        Objects.requireNonNull(stream, "stream");
    }
}
