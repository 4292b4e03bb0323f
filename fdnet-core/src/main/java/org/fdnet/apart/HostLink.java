package org.fdnet.apart;

import java.util.ArrayList;
import java.util.List;

/**
 * One host's link to the rig's bridge, and the faults put on it: a veth pair whose end {@code eth0} is in the host's
 * namespace and whose other end is on the bridge in the rig's namespace.
 *
 * <p>Each fault is a rule set of the rig's own — an nftables table in the host's namespace ({@code fdnet_apart_…}) or a
 * TBF queue on the pair's two ends — so lifting it removes exactly what was added. Drops are silent: a packet is
 * discarded, nobody answers with a reset, exactly as when a cable is pulled or a radio is out of range.
 */
final class HostLink {
    /** The host's end of its veth pair, inside its namespace. */
    static final String HOST_DEVICE = "eth0";
    private static final String BLACKHOLE = "fdnet_apart_blackhole";
    private static final String LOSS = "fdnet_apart_loss";
    /** How long a throttled link may queue before TBF drops: the buffer of a slow radio, not an endless one. */
    private static final String THROTTLE_LATENCY = "400ms";

    private final String rigNamespace;
    private final String bridgeDevice;
    private final String namespace;

    /**
     * @param rigNamespace the rig's namespace (the bridge's)
     * @param bridgeDevice the pair's end on the bridge
     * @param namespace    the host's namespace
     */
    HostLink(String rigNamespace, String bridgeDevice, String namespace) {
        this.rigNamespace = rigNamespace;
        this.bridgeDevice = bridgeDevice;
        this.namespace = namespace;
    }

    /** Drops every packet in and out of the host's link, silently, until {@link #heal}. */
    void blackhole() {
        replaceTable(BLACKHOLE, "drop");
    }

    /** Lifts {@link #blackhole}; loss and throttling stay. */
    void heal() {
        deleteTable(BLACKHOLE);
    }

    /**
     * Drops each packet in or out of the host's link with probability {@code percent} %; 0 lifts it.
     *
     * @throws IllegalArgumentException when {@code percent} is outside 0–100
     */
    void loss(int percent) {
        if (percent < 0 || percent > 100) {
            throw new IllegalArgumentException("loss must be 0 to 100 %, was " + percent);
        }
        if (percent == 0) {
            deleteTable(LOSS);
        } else {
            // numgen's value is 0-99: at 100 % every packet goes, which is a plain drop.
            replaceTable(LOSS, percent == 100 ? "drop" : "numgen random mod 100 < " + percent + " drop");
        }
    }

    /**
     * Limits the link to {@code kbitPerSecond} in each direction (TBF on both ends of the pair).
     *
     * @throws IllegalArgumentException when {@code kbitPerSecond} is not positive
     */
    void throttle(int kbitPerSecond) {
        if (kbitPerSecond <= 0) {
            throw new IllegalArgumentException("a throttled link needs a rate above 0 kbit/s, was " + kbitPerSecond);
        }
        // TBF needs a bucket of at least one rate's worth of a timer tick; 50 ms of the rate, at least 16 KiB.
        long burstBytes = Math.max(16 * 1024L, kbitPerSecond * 1000L / 8 / 20);
        List<String> tbf = List.of("root", "tbf", "rate", kbitPerSecond + "kbit", "burst", Long.toString(burstBytes),
                "latency", THROTTLE_LATENCY);
        tc(namespace, "replace", HOST_DEVICE, tbf);
        tc(rigNamespace, "replace", bridgeDevice, tbf);
    }

    /** Lifts {@link #throttle}. */
    void unthrottle() {
        for (String[] end : new String[][] {{namespace, HOST_DEVICE}, {rigNamespace, bridgeDevice}}) {
            String shown = SystemCommand.run(SystemCommand.tool("ip"), "netns", "exec", end[0],
                    SystemCommand.tool("tc"), "qdisc", "show", "dev", end[1]);
            if (shown.contains("tbf")) {
                tc(end[0], "del", end[1], List.of("root"));
            }
        }
    }

    /** Lifts every fault: the link is as the rig made it. */
    void clear() {
        heal();
        loss(0);
        unthrottle();
    }

    /** The nftables tables of the rig now in the host's namespace (for checks and for {@code fdnet apart status}). */
    List<String> faultTables() {
        String listed = SystemCommand.run(SystemCommand.tool("ip"), "netns", "exec", namespace,
                SystemCommand.tool("nft"), "list", "tables");
        return listed.lines().map(String::strip).filter(l -> l.contains("fdnet_apart_"))
                .map(l -> l.substring(l.lastIndexOf(' ') + 1)).toList();
    }

    /** The queue discipline on the host's end of the link, as {@code tc} shows it. */
    String queue() {
        return SystemCommand.run(SystemCommand.tool("ip"), "netns", "exec", namespace, SystemCommand.tool("tc"),
                "qdisc", "show", "dev", HOST_DEVICE).strip();
    }

    /** Replaces table {@code name} (atomically) by one whose input and output chains apply {@code verdict} on the link. */
    private void replaceTable(String name, String verdict) {
        String script = "table inet " + name + " {}\n"
                + "delete table inet " + name + "\n"
                + "table inet " + name + " {\n"
                + "  chain in { type filter hook input priority filter; policy accept; iifname \"" + HOST_DEVICE + "\" "
                + verdict + "; }\n"
                + "  chain out { type filter hook output priority filter; policy accept; oifname \"" + HOST_DEVICE
                + "\" " + verdict + "; }\n"
                + "}\n";
        nft(script);
    }

    /** Removes table {@code name} when it is there (declaring it first makes the delete always valid). */
    private void deleteTable(String name) {
        nft("table inet " + name + " {}\ndelete table inet " + name + "\n");
    }

    private void nft(String script) {
        SystemCommand.run(List.of(SystemCommand.tool("ip"), "netns", "exec", namespace, SystemCommand.tool("nft"),
                "-f", "-"), script);
    }

    private static void tc(String ns, String verb, String device, List<String> rest) {
        List<String> argv = new ArrayList<>(List.of(SystemCommand.tool("ip"), "netns", "exec", ns,
                SystemCommand.tool("tc"), "qdisc", verb, "dev", device));
        argv.addAll(rest);
        SystemCommand.run(argv, null);
    }
}
