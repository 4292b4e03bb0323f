/**
 * A running network's control object: the {@code RunningNetwork} interface of {@code fdnet.idl}, published by
 * {@code fdnet run} and {@code fdnet demo}, and the client that makes it a {@link org.fdnet.control.LiveNetwork}
 * again in another process (the editor attached to it, {@code fdnet control}).
 *
 * <pre>
 *   run's process                                               tool's process
 *   Controller ◀── LocalLiveNetwork ◀── RunningNetworkImpl ◀══ two-way calls ══ RemoteLiveNetwork ◀── editor, fdnet control
 *                   (or a LiveNetwork     │  definitions as .fdn text,            │ watchdog: ping every 500 ms
 *                    across hosts)        │  validated as every .fdn file         │
 *                                         └══ changeSettled / valuesSampled ══▶ ListenerServant ──▶ LiveNetworkListener
 *                                             (10 Hz, one thread per subscriber)    disconnected(reason), once
 *
 *   ControlPublication: corbaloc::127.0.0.1:PORT/FDNetControl (own ORB, persistent key), or the naming service
 *   (name, kind "fdnet-network"); both write ~/.fdnet/run/NAME.ref (RunFiles) for --attach NAME on this machine.
 * </pre>
 *
 * Safety: the control object listens on 127.0.0.1 unless the user names another address ({@code --control-host});
 * anyone who reaches it can change the network.
 */
package org.fdnet.corba.control;
