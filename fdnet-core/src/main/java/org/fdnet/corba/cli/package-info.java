/**
 * The distribution commands: {@code fdnet naming}, {@code fdnet host}, {@code fdnet bench corba}.
 */
package org.fdnet.corba.cli;
