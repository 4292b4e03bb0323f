/**
 * A network's run, start to end, the same whether it runs on this machine or over several hosts: the one
 * lifecycle ({@link org.fdnet.run.NetworkRun}) behind {@code fdnet run} and the editor's Run. It sits above the
 * engine ({@code org.fdnet.runtime}) and the distribution ({@code org.fdnet.corba}); nothing below imports it.
 *
 * <pre>
 *   RunCommand / editor ─▶ RunOptions ─▶ NetworkRun ─▶ RunIdentity (id, network, .fdn + SHA-256, start, hosts)
 *        ├─ one host:   LocalTarget       (RuntimeNetwork [+ SimulatedPlant] [+ LoggerClient of the run])
 *        └─ many hosts: DistributedTarget (corba.DistributedRun: each host records its part of the run)
 *   NetworkControl ◀─ --load / --set / --param, stdin commands, the control object
 *   status line each second ─▶ RunSummary ─▶ stop: every host's part ends, its events committed
 * </pre>
 */
package org.fdnet.run;
