/**
 * The editor's commands, added to {@code fdnet} through {@link org.fdnet.cli.CommandProvider}:
 * {@code fdnet hi [FILE]} (with {@code --screenshot} for documentation) and {@code fdnet bench hi}.
 */
package org.fdnet.hi.cli;
