/**
 * The runtime's command-line pieces: the standard-input commands of a running network
 * ({@link org.fdnet.runtime.cli.ControlCommands}), the {@code --set} and {@code --param} parsers
 * ({@code ValueAssignment}, {@code ParameterAssignment}, also used by {@code fdnet bench roq}), the duration parser, and the simulated-plant
 * seam. {@code fdnet run} itself is {@code org.fdnet.run}'s, which uses them; {@code fdnet bench core}
 * ({@code BenchCoreCommand}, same package) is fdnet-core/bench's.
 *
 * <pre>
 *   stdin "hold Walk" ──▶ ControlCommands ──▶ NetworkControl (the Controller, or DistributedControl) ──▶ "ok: …"
 * </pre>
 */
package org.fdnet.runtime.cli;
