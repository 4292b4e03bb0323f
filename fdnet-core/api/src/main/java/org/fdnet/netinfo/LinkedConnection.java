package org.fdnet.netinfo;

/** A connection together with the module that declares it (a connection may join nodes of other modules). */
public record LinkedConnection(String module, ConnectionInfo connection) {
}
