/**
 * The distribution commands: {@code fdnet naming}, {@code fdnet host}, {@code fdnet control}, and the options
 * they share ({@code --naming}, {@code --bind}, {@code --as}, {@code --control-host}). {@code fdnet bench corba} is fdnet-core/bench's
 * ({@code org.fdnet.corba.bench}).
 */
package org.fdnet.corba.cli;
