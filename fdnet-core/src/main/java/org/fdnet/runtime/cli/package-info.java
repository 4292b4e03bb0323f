/**
 * The runtime's command-line pieces: {@code fdnet bench core}, the standard-input commands of a running network
 * ({@link org.fdnet.runtime.cli.ControlCommands}), the {@code --set} and duration parsers, and the simulated-plant
 * seam. {@code fdnet run} itself is {@code org.fdnet.run}'s, which uses them.
 *
 * <pre>
 *   stdin "hold Walk" ──▶ ControlCommands ──▶ NetworkControl (the Controller, or DistributedControl) ──▶ "ok: …"
 * </pre>
 */
package org.fdnet.runtime.cli;
