/**
 * The runtime's commands, added to {@code fdnet} through {@link org.fdnet.cli.CommandProvider}:
 * {@code fdnet run FILE} and the benchmark {@code fdnet bench core}.
 *
 * <pre>
 *   fdnet run FILE ──▶ NetworkRepository.load ──▶ RuntimeNetwork.start ──▶ --load / --set / --param
 *        └── status line each second (firings, values, events, failed) ──▶ summary ──▶ close
 *   stdin "hold Walk" ──▶ ControlCommands ──▶ NetworkControl (the Controller, or DistributedControl) ──▶ "ok: …"
 * </pre>
 */
package org.fdnet.runtime.cli;
