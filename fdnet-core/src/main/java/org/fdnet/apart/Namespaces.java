package org.fdnet.apart;

import java.io.IOException;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** The machine's named network namespaces, through {@code ip netns}: listed, added, emptied and removed. Root only. */
final class Namespaces {
    private static final Logger LOG = LoggerFactory.getLogger(Namespaces.class);
    private static final Pattern ADDRESS = Pattern.compile("inet ([0-9.]+)/");
    private static final long PROCESS_END_SECONDS = 10;

    private Namespaces() {
    }

    /** The namespaces on this machine, as {@code ip netns list} names them. */
    static List<String> list() {
        String listed = SystemCommand.run(SystemCommand.tool("ip"), "netns", "list");
        return listed.lines().map(String::strip).filter(l -> !l.isEmpty()).map(l -> l.split(" ")[0]).toList();
    }

    /** Makes namespace {@code ns}. */
    static void add(String ns) {
        ip("netns", "add", ns);
    }

    /** Kills every process left in {@code ns}, then deletes it; a namespace already gone is no failure. */
    static void remove(String ns) {
        if (!list().contains(ns)) {
            return;
        }
        String pids = SystemCommand.attempt(List.of(SystemCommand.tool("ip"), "netns", "pids", ns), null).output();
        List<ProcessHandle> left = pids.lines().map(String::strip).filter(l -> l.matches("[0-9]+"))
                .map(Long::parseLong).map(ProcessHandle::of).flatMap(Optional::stream).toList();
        for (ProcessHandle p : left) {
            LOG.info("apart rig: killing process {} left in {}", p.pid(), ns);
            p.destroyForcibly();
        }
        for (ProcessHandle p : left) {
            try {
                p.onExit().get(PROCESS_END_SECONDS, TimeUnit.SECONDS);
            } catch (Exception e) {
                LOG.warn("process {} in {} did not end: {}", p.pid(), ns, e.toString());
            }
        }
        ip("netns", "del", ns);
    }

    /**
     * The IPv4 address of the link {@link HostLink#HOST_DEVICE} in {@code ns}.
     *
     * @throws IllegalStateException when it has none: {@code ns} is not a host of a working rig
     */
    static InetAddress addressOf(String ns) {
        String shown = SystemCommand.run(SystemCommand.tool("ip"), "-n", ns, "-o", "-4", "addr", "show", "dev",
                HostLink.HOST_DEVICE);
        Matcher m = ADDRESS.matcher(shown);
        if (!m.find()) {
            throw new IllegalStateException("namespace " + ns + " has no address on " + HostLink.HOST_DEVICE
                    + ": it is not a host of a working rig (fdnet apart down removes it)");
        }
        try {
            return InetAddress.getByName(m.group(1));
        } catch (UnknownHostException e) {
            throw new IllegalStateException("namespace " + ns + " has address " + m.group(1), e);
        }
    }

    /** Runs {@code ip ARGS}. */
    static void ip(String... args) {
        List<String> argv = new ArrayList<>(List.of(SystemCommand.tool("ip")));
        argv.addAll(List.of(args));
        SystemCommand.run(argv, null);
    }

    /** @throws IllegalStateException in one line when this process is not root */
    static void requireRoot() {
        Object uid;
        try {
            uid = Files.getAttribute(Path.of("/proc/self"), "unix:uid");
        } catch (IOException | UnsupportedOperationException e) {
            uid = -1;
        }
        if (!Integer.valueOf(0).equals(uid)) {
            throw new IllegalStateException("the apart rig needs root: it makes network namespaces, veth pairs, a"
                    + " bridge and nftables rules to put hosts on addresses of their own (run it as root)");
        }
    }
}
