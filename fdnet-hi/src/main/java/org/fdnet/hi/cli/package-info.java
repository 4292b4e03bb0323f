/**
 * The editor's commands, added to {@code fdnet} through {@link org.fdnet.cli.spi.CommandProvider}:
 * {@code fdnet hi [FILE]} (with {@code --screenshot} for documentation). {@code fdnet bench hi} ({@code BenchHiCommand}, same
 * package) is in fdnet-hi/bench, registered there by {@code HiBenchmarks}: the editor's jar carries no benchmark.
 */
package org.fdnet.hi.cli;
