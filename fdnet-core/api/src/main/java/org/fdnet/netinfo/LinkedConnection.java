package org.fdnet.netinfo;

/**
 * A connection together with the module that declares it (a connection may join nodes of other modules).
 *
 * @param module     the full name of the module that declares the connection
 * @param connection the Reader or Writer
 */
public record LinkedConnection(String module, ConnectionInfo connection) {
}
