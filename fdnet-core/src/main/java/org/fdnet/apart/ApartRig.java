package org.fdnet.apart;

import java.io.IOException;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Hosts that are really apart on one machine: each host gets a Linux network namespace of its own, with its own
 * address, joined to the others by a veth pair on a bridge that lives in a namespace of the rig's own. Nothing of
 * the machine's own network (its interfaces, routes, firewall) is touched, and nothing leaves the machine.
 *
 * <pre>
 *   namespace PREFIX-PID (the rig's)          namespace PREFIX-PID-flyer      namespace PREFIX-PID-crawler
 *     br0 ── v0 ═══════════════════════════════ eth0 10.231.X.1/24
 *      └──── v1 ═════════════════════════════════════════════════════════════ eth0 10.231.X.2/24
 * </pre>
 *
 * <p>A process runs on a host through {@link #command}: its argv prefixed with {@code ip netns exec}. Faults are
 * put on a host's link ({@link #blackhole}, {@link #loss}, {@link #throttle}) and lifted ({@link #heal},
 * {@link #clear}); see {@link HostLink}. The subnet's third byte X is one no other rig on the machine uses.
 *
 * <p>Hazards: it needs root. {@link #close} removes every namespace it made (and so every link, table and queue in
 * them) after killing what still runs in them; a JVM shutdown hook does the same when the process ends without
 * closing it, and {@link #sweep} removes what a rig killed with {@code kill -9} left behind (its names carry its
 * process id; {@link #create} sweeps its prefix first).
 */
public final class ApartRig implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(ApartRig.class);
    /** The private range the rigs' subnets are taken from: 10.231.X.0/24. */
    private static final int FIRST_BYTE = 10;
    private static final int SECOND_BYTE = 231;
    private static final int MAX_HOSTS = 250;
    private static final String BRIDGE = "br0";
    /** Serialises the choice of subnets between rigs made at once on this machine. */
    private static final Path CHOICE_LOCK = Path.of("/run/fdnet-apart.lock");
    private static final Object CHOICE_LOCK_IN_THIS_JVM = new Object();
    private static final Pattern USED_SUBNET = Pattern.compile("inet " + FIRST_BYTE + "\\." + SECOND_BYTE + "\\.([0-9]+)\\.");

    private final RigNames names;
    private final int subnet;
    private final Map<String, HostLink> links = new LinkedHashMap<>();
    private final Map<String, InetAddress> addresses = new LinkedHashMap<>();
    private final List<String> made = new ArrayList<>();
    private final Thread shutdownHook;
    /** Whether this object made the rig (and removes it), or found one another process made ({@link #find}). */
    private final boolean owner;
    private boolean closed;

    private ApartRig(RigNames names, int subnet, boolean owner) {
        this.names = names;
        this.subnet = subnet;
        this.owner = owner;
        this.shutdownHook = new Thread(this::closeQuietly, "apart-rig-cleanup-" + names.rigNamespace());
    }

    /**
     * Makes one namespace per host, each with its own address on one bridge.
     *
     * @param prefix    what the rig's names start with (a letter, then letters, digits or '_'); leftovers of a dead
     *                  rig with this prefix are removed first
     * @param hostNames the hosts, each a namespace {@code PREFIX-PID-NAME} and an address 10.231.X.(index+1)
     * @return the rig, ready: every host reaches every other by its address
     * @throws IllegalStateException    when this process is not root (one line saying so and why), a tool is missing,
     *                                  or a step fails (what was made so far is removed again)
     * @throws IllegalArgumentException when a name is not allowed, repeated, or there are no or too many hosts
     */
    public static ApartRig create(String prefix, List<String> hostNames) {
        RigNames.requirePrefix(prefix);
        if (hostNames.isEmpty() || hostNames.size() > MAX_HOSTS) {
            throw new IllegalArgumentException("a rig has 1 to " + MAX_HOSTS + " hosts, was given " + hostNames.size());
        }
        Set<String> seen = new HashSet<>();
        for (String h : hostNames) {
            RigNames.requireHost(h);
            if (!seen.add(h)) {
                throw new IllegalArgumentException("host '" + h + "' is named twice");
            }
        }
        Namespaces.requireRoot();
        sweep(prefix);
        RigNames names = new RigNames(prefix, ProcessHandle.current().pid());
        synchronized (CHOICE_LOCK_IN_THIS_JVM) {
            try (FileChannel lockFile = FileChannel.open(CHOICE_LOCK, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
                 FileLock ignored = lockFile.lock()) {
                ApartRig rig = new ApartRig(names, freeSubnet(), true);
                Runtime.getRuntime().addShutdownHook(rig.shutdownHook);
                try {
                    rig.build(hostNames);
                } catch (RuntimeException e) {
                    rig.closeQuietly();
                    throw e;
                }
                LOG.info("apart rig {} up: {}", names.rigNamespace(), rig.addresses);
                return rig;
            } catch (IOException e) {
                throw new IllegalStateException("cannot lock " + CHOICE_LOCK + " to choose the rig's subnet: "
                        + e.getMessage(), e);
            }
        }
    }

    /**
     * Removes what rigs with {@code prefix} left behind: their namespaces whose owning process is gone (and what runs in
     * them). Rigs of live processes are left alone.
     *
     * @param prefix the rigs' prefix
     * @return the namespaces removed
     */
    public static List<String> sweep(String prefix) {
        RigNames.requirePrefix(prefix);
        Namespaces.requireRoot();
        List<String> removed = new ArrayList<>();
        List<String> stale = new ArrayList<>();
        for (String ns : Namespaces.list()) {
            Optional<Long> owner = RigNames.ownerOf(prefix, ns);
            if (owner.isPresent() && ProcessHandle.of(owner.get()).map(ProcessHandle::isAlive).orElse(false)) {
                continue;
            }
            owner.ifPresent(pid -> stale.add(ns));
        }
        // Hosts before the rig's own namespace, as close does: the longest names first.
        stale.sort((a, b) -> Integer.compare(b.length(), a.length()));
        for (String ns : stale) {
            Namespaces.remove(ns);
            removed.add(ns);
        }
        if (!removed.isEmpty()) {
            LOG.info("apart rig sweep removed {}", removed);
        }
        return removed;
    }

    /**
     * The rig with {@code prefix} that a live process made, to run commands on its hosts and put faults on their links
     * from another process ({@code fdnet apart exec}, {@code fdnet apart fault}). Closing what this returns removes
     * nothing: the rig stays its maker's.
     *
     * @return the rig; empty when no live process has one with this prefix
     * @throws IllegalStateException when several live processes have one (each is named)
     */
    public static Optional<ApartRig> find(String prefix) {
        RigNames.requirePrefix(prefix);
        Map<Long, List<String>> byOwner = new LinkedHashMap<>();
        for (String ns : Namespaces.list()) {
            RigNames.ownerOf(prefix, ns)
                    .filter(pid -> ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false))
                    .ifPresent(pid -> byOwner.computeIfAbsent(pid, p -> new ArrayList<>()).add(ns));
        }
        if (byOwner.isEmpty()) {
            return Optional.empty();
        }
        if (byOwner.size() > 1) {
            throw new IllegalStateException("several rigs named " + prefix + " are up, made by processes "
                    + byOwner.keySet() + ": stop all but one");
        }
        long pid = byOwner.keySet().iterator().next();
        RigNames names = new RigNames(prefix, pid);
        Map<Integer, String> hostsByIndex = new TreeMap<>();
        Map<String, InetAddress> found = new LinkedHashMap<>();
        for (String ns : byOwner.get(pid)) {
            if (ns.equals(names.rigNamespace())) {
                continue;
            }
            String host = ns.substring(names.rigNamespace().length() + 1);
            InetAddress address = Namespaces.addressOf(ns);
            hostsByIndex.put((address.getAddress()[3] & 0xff) - 1, host);
            found.put(host, address);
        }
        int subnet = found.isEmpty() ? 0 : found.values().iterator().next().getAddress()[2] & 0xff;
        ApartRig rig = new ApartRig(names, subnet, false);
        hostsByIndex.forEach((index, host) -> {
            rig.links.put(host, new HostLink(names.rigNamespace(), "v" + index, names.hostNamespace(host)));
            rig.addresses.put(host, found.get(host));
        });
        return Optional.of(rig);
    }

    /** The process that made this rig and removes it. */
    public long ownerPid() {
        return names.pid();
    }

    /**
     * The address of host {@code name}.
     *
     * @throws IllegalArgumentException when the rig has no such host
     */
    public InetAddress address(String name) {
        requireKnown(name);
        return addresses.get(name);
    }

    /**
     * {@code argv} as a command that runs on host {@code name}: inside its namespace, where only its own address and
     * loopback exist.
     *
     * @throws IllegalArgumentException when the rig has no such host
     */
    public List<String> command(String name, List<String> argv) {
        List<String> prefixed = new ArrayList<>(List.of(SystemCommand.tool("ip"), "netns", "exec", namespace(name)));
        prefixed.addAll(argv);
        return prefixed;
    }

    /**
     * The network namespace host {@code name} runs in.
     *
     * @throws IllegalArgumentException when the rig has no such host
     */
    public String namespace(String name) {
        requireKnown(name);
        return names.hostNamespace(name);
    }

    /** The hosts, in the order given to {@link #create}. */
    public List<String> hosts() {
        return List.copyOf(links.keySet());
    }

    /** The rig's subnet, e.g. {@code 10.231.3.0/24}. */
    public String subnet() {
        return FIRST_BYTE + "." + SECOND_BYTE + "." + subnet + ".0/24";
    }

    /** The rig's own namespace, which holds the bridge. */
    public String rigNamespace() {
        return names.rigNamespace();
    }

    /** Silently drops every packet in and out of host {@code name}'s link (no reset is sent) until {@link #heal}. */
    public void blackhole(String name) {
        link(name).blackhole();
    }

    /** Lifts {@link #blackhole}; a loss or throttle on the link stays. */
    public void heal(String name) {
        link(name).heal();
    }

    /**
     * Drops each packet in or out of host {@code name}'s link with probability {@code percent} %; 0 lifts it.
     *
     * @throws IllegalArgumentException when {@code percent} is outside 0–100
     */
    public void loss(String name, int percent) {
        link(name).loss(percent);
    }

    /**
     * Limits host {@code name}'s link to {@code kbitPerSecond} each way (TBF); {@link #clear} lifts it.
     *
     * @throws IllegalArgumentException when {@code kbitPerSecond} is not positive
     */
    public void throttle(String name, int kbitPerSecond) {
        link(name).throttle(kbitPerSecond);
    }

    /** Lifts every fault on host {@code name}'s link. */
    public void clear(String name) {
        link(name).clear();
    }

    /** The rig's nftables tables in host {@code name}'s namespace, e.g. {@code [fdnet_apart_blackhole]}. */
    public List<String> faultTables(String name) {
        return link(name).faultTables();
    }

    /** The queue discipline on host {@code name}'s end of its link, as {@code tc qdisc show} prints it. */
    public String queue(String name) {
        return link(name).queue();
    }

    /**
     * Kills what still runs in the rig's namespaces and removes them, with their links, tables and queues; does
     * nothing on a rig another process made ({@link #find}).
     *
     * @throws IllegalStateException naming what could not be removed (everything else is removed all the same)
     */
    @Override
    public void close() {
        if (!owner) {
            return;
        }
        List<String> failures = removeAll();
        try {
            Runtime.getRuntime().removeShutdownHook(shutdownHook);
        } catch (IllegalStateException shuttingDown) {
            // the hook is running or about to: nothing to remove
        }
        if (!failures.isEmpty()) {
            throw new IllegalStateException("apart rig " + names.rigNamespace() + " could not remove: "
                    + String.join("; ", failures));
        }
    }

    private void closeQuietly() {
        List<String> failures = removeAll();
        if (!failures.isEmpty()) {
            LOG.warn("apart rig {} could not remove: {}", names.rigNamespace(), failures);
        }
    }

    private synchronized List<String> removeAll() {
        if (closed) {
            return List.of();
        }
        closed = true;
        List<String> failures = new ArrayList<>();
        for (int i = made.size() - 1; i >= 0; i--) {
            try {
                Namespaces.remove(made.get(i));
            } catch (IllegalStateException e) {
                failures.add(e.getMessage());
            }
        }
        LOG.info("apart rig {} removed", names.rigNamespace());
        return failures;
    }

    private void build(List<String> hostNames) {
        String rig = names.rigNamespace();
        addNamespace(rig);
        Namespaces.ip("-n", rig, "link", "add", BRIDGE, "type", "bridge");
        Namespaces.ip("-n", rig, "link", "set", BRIDGE, "up");
        for (int i = 0; i < hostNames.size(); i++) {
            String host = hostNames.get(i);
            String ns = names.hostNamespace(host);
            String bridgeEnd = "v" + i;
            addNamespace(ns);
            Namespaces.ip("-n", rig, "link", "add", bridgeEnd, "type", "veth", "peer", "name", HostLink.HOST_DEVICE,
                    "netns", ns);
            Namespaces.ip("-n", rig, "link", "set", bridgeEnd, "master", BRIDGE, "up");
            InetAddress address = hostAddress(i);
            Namespaces.ip("-n", ns, "addr", "add", address.getHostAddress() + "/24", "dev", HostLink.HOST_DEVICE);
            Namespaces.ip("-n", ns, "link", "set", HostLink.HOST_DEVICE, "up");
            Namespaces.ip("-n", ns, "link", "set", "lo", "up");
            links.put(host, new HostLink(rig, bridgeEnd, ns));
            addresses.put(host, address);
        }
    }

    private void addNamespace(String ns) {
        Namespaces.add(ns);
        made.add(ns);
    }

    private InetAddress hostAddress(int index) {
        try {
            return InetAddress.getByAddress(new byte[] {FIRST_BYTE, (byte) SECOND_BYTE, (byte) subnet, (byte) (index + 1)});
        } catch (UnknownHostException e) {
            throw new IllegalStateException("cannot make address " + index, e);
        }
    }

    /** A subnet byte X that no namespace on this machine has an address in (10.231.X.0/24). */
    private static int freeSubnet() {
        SystemCommand.Result r = SystemCommand.attempt(List.of(SystemCommand.tool("ip"), "-all", "netns", "exec",
                SystemCommand.tool("ip"), "-o", "-4", "addr", "show"), null);
        Set<Integer> used = new HashSet<>();
        Matcher m = USED_SUBNET.matcher(r.output());
        while (m.find()) {
            used.add(Integer.parseInt(m.group(1)));
        }
        for (int x = 1; x < 255; x++) {
            if (!used.contains(x)) {
                return x;
            }
        }
        throw new IllegalStateException("every subnet 10.231.X.0/24 is taken by another rig; remove stale ones with"
                + " fdnet apart sweep");
    }

    private HostLink link(String name) {
        requireKnown(name);
        return links.get(name);
    }

    private void requireKnown(String name) {
        if (!links.containsKey(name)) {
            throw new IllegalArgumentException("no host '" + name + "' in apart rig " + names.rigNamespace()
                    + " (hosts: " + String.join(", ", links.keySet()) + ")");
        }
    }
}
