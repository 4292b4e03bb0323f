/**
 * Node classes of {@code fdnet bench corba}; built in on every host so the benchmark can place them remotely.
 */
package org.fdnet.corba.bench;
