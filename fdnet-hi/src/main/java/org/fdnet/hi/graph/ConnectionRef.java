package org.fdnet.hi.graph;

import org.fdnet.netinfo.ConnectionInfo;

/** A connection with the module that declares it: what the graph selects when a Reader or Writer is clicked. */
public record ConnectionRef(String module, ConnectionInfo connection) {
}
