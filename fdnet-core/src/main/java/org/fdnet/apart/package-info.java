/**
 * Hosts that are really apart on one machine: the apart rig runs each FDNet process in a Linux network namespace of
 * its own, with its own address, so that traffic between them crosses real (virtual) links that faults can be put
 * on — a silent partition, random loss, a slow link — as a robot's radio meets them.
 *
 * <pre>
 *   ApartRig.create(prefix, [naming, flyer, crawler, …])       (root only)
 *        │  ip netns add PREFIX-PID (bridge br0)  +  per host: ip netns add PREFIX-PID-HOST,
 *        │  veth pair vN ═ eth0 (10.231.X.N+1/24), lo up
 *        ▼
 *   rig.command(host, argv) ── ip netns exec PREFIX-PID-HOST argv…     (the process sees only its address and lo)
 *   rig.blackhole / heal / loss / throttle / clear(host)
 *        │  HostLink: nftables table fdnet_apart_blackhole | fdnet_apart_loss in the host's namespace,
 *        │            TBF on both ends of its veth pair
 *        ▼
 *   rig.close() / shutdown hook / ApartRig.sweep(prefix) ── kill what runs inside, ip netns del each namespace
 * </pre>
 *
 * Nothing is added to the machine's own namespace: the bridge lives in the rig's namespace, so the machine's
 * interfaces, routes and firewall are untouched and no packet leaves the machine.
 */
package org.fdnet.apart;
