/**
 * Distribution: one FDNetwork over several host processes, through CORBA (JacORB 3.9, {@code idl/fdnet.idl}).
 *
 * <pre>
 *   fdnet run FILE ── DeploymentPlan (node → host; stand-ins; links) ── NetworkDeployment
 *        │                     createNode / createStandIn / connect / acceptLink / forward, then ping
 *        ▼
 *   HostDirectory (naming service: "flyer", "crawler" …)
 *        │
 *   Host "flyer" (HostServant over its LocalNetwork)           Host "crawler"
 *     Data main/map ──observer──▶ OutboundLink ═══deliver(ValueBatch)══▶ InboundLink ──inject──▶ stand-in main/map
 *                                  ring + window of                      in sequence order        │ Reader
 *                                  two-way calls ◀═══ next expected seq ═╝                        ▼
 *                                                                                         Relation main/plan
 * </pre>
 *
 * Same-host connections never leave their host's engine. Cross-host values go in batches over two-way
 * calls with at most {@link org.fdnet.corba.LinkSettings#window()} in flight (a oneway flood overflows
 * JacORB's POA queue and drops calls); sequence numbers keep them in order, and a value leaves the sender
 * only when the receiver has applied it, so a restarted receiver gets everything it missed. The engine hands
 * values to a link under its commit lock, so a link never waits for a reply there: an idle link's lone value
 * goes ahead from the writer's thread as a one-way call, kept by the sender until a later two-way call's reply
 * covers it (a sender thread confirms it shortly after, sending it again; see {@link org.fdnet.corba.OutboundLink}),
 * everything else through the link's sender threads.
 *
 * <p>Class map: {@link org.fdnet.corba.OrbRuntime} starts ORBs (JDK 17 fixes) from
 * {@link org.fdnet.corba.OrbSettings} (every JacORB key); {@link org.fdnet.corba.NamingService} runs
 * JacORB's NameServer; {@link org.fdnet.corba.HostProcess} is one host; {@link org.fdnet.corba.LocalNetwork}
 * is the seam to the engine that runs a host's nodes.
 *
 * <p>Live changes: {@link org.fdnet.corba.DistributedControl} (the {@link org.fdnet.runtime.NetworkControl} of a
 * distributed run) prepares a change on every host it touches and commits it only when none refused; each
 * host's {@link org.fdnet.corba.LiveChanges} checks and executes it through its engine's Controller.
 * <pre>
 *   "hold main" ─▶ DistributedControl ─prepareChange─▶ Host flyer, Host crawler … ─▶ all ""? ─commitChange─▶ each
 *                                                                           a reason? ─abortChange──▶ the prepared
 * </pre>
 * Structural changes (load, unload, an edit, a Relation's Paste on any host) change the deployment itself: the
 * coordinator plans the whole network after the change ({@link org.fdnet.corba.DeploymentPlan#next}), derives each
 * host's part ({@link org.fdnet.corba.PlanDifference}) and prepares it there ({@link org.fdnet.corba.ShareChanges}:
 * allowed classes, free names), then closes the links that go, commits on every host and opens the new links.
 * <pre>
 *   Relation on flyer ─Servants─▶ CoordinatorView ══describeNetwork / applyEdit══▶ CoordinatorServant (fdnet run)
 *                                                   DistributedControl ─prepareShareChange─▶ every host it touches
 *                                                   all ""? close links ─commitChange─▶ each ─▶ acceptLink/forward
 * </pre>
 * The run's control object (a running network reachable from tools: {@code fdnet control}, the editor's
 * {@code --attach}) is in {@code org.fdnet.corba.control}.
 * Logging: every host records its engine's events, less its stand-ins', as its part of the one network run
 * the coordinator hands over at deployment ({@code recordRun}: {@code RunIdentity} + logger address, or the host's
 * own {@code fdnet host --logger}), through a {@link org.fdnet.corba.HostRecording} of its own; {@code endRun} at
 * the end commits it. At deployment each host is also sized for the run ({@code sizeEngine}: the run's
 * {@code --workers}, else the host's own count) and, for {@code --trace}, told to keep its own events in a bounded
 * {@link org.fdnet.corba.HostTrace}, which the run's {@link org.fdnet.corba.TraceCollector} drains (pulled, so a slow
 * tracer costs dropped-and-counted lines, never a host's progress or memory):
 * <pre>
 *   host engine ─▶ HostTrace [≤ capacity; full: drop, count] ◀─takeTrace─ TraceCollector (fdnet run) ─▶ TraceOutput
 * </pre>
 * The run's life around a deployment is {@code org.fdnet.run}'s.
 *
 * <p>Permissions (with TLS): every request is checked against the network's signed permissions for the certificate of
 * the connection that carries it, before the servant changes or reveals anything.
 * <pre>
 *   request ─▶ CallerInterceptor (TLS session of its connection ─▶ certificate name, kept in the session)
 *           ─▶ HostServant / CoordinatorServant / RunningNetworkImpl ─▶ Caller.require(right, node or module)
 *                 allowed: as before        refused: NO_PERMISSION (or a refused change) naming certificate,
 *                                                    node or module and right; nothing applied
 * </pre>
 *
 * <p>Child processes: benchmarks and multi-process tests start {@code fdnet} commands in child JVMs through
 * {@link org.fdnet.corba.FdnetChildProcess}, with the JVM options the launcher would give the same command (the short
 * commands of {@link org.fdnet.corba.QuickJitCommands} stop their JIT at C1).
 */
package org.fdnet.corba;
