package org.fdnet.corba;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.ThreadLocalRandom;
import org.omg.CORBA.CompletionStatus;
import org.omg.CORBA.TRANSIENT;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A fault injector in the transport of cross-host links, for soak tests (Fast DDS tests its transport the same way):
 * while it is on, each {@code deliver} call of this process's {@link OutboundLink}s is delayed by {@code delay} ms and
 * a share {@code drop} of them is dropped — half before the peer sees the batch (a lost request), half after it
 * applied it (a lost reply: the sender resends values the peer already has).
 *
 * <p>Off by default: without {@code fdnet host --link-faults FILE} every call goes straight through. With it, the
 * file switches the faults on and off while the host runs: {@code drop=0.2,delay=20} turns them on, an empty or
 * missing file off. The file is read at most every {@value #RECHECK_MILLIS} ms.
 */
public final class LinkFaults {
    private static final Logger LOG = LoggerFactory.getLogger(LinkFaults.class);
    private static final long RECHECK_MILLIS = 100;
    private static volatile LinkFaults installed;

    /** The faults the switch file asks for now. */
    record Setting(double dropShare, int delayMillis) {
        static final Setting OFF = new Setting(0, 0);

        Setting {
            if (!(dropShare >= 0 && dropShare <= 1)) {
                throw new IllegalArgumentException("drop must be 0..1, was " + dropShare);
            }
            if (delayMillis < 0 || delayMillis > 10_000) {
                throw new IllegalArgumentException("delay must be 0..10000 ms, was " + delayMillis);
            }
        }

        boolean on() {
            return dropShare > 0 || delayMillis > 0;
        }
    }

    private final Path switchFile;
    private volatile Setting setting = Setting.OFF;
    private volatile long checkedAtMillis;

    private LinkFaults(Path switchFile) {
        this.switchFile = switchFile;
    }

    /** Makes {@code switchFile} switch this process's link faults on and off. */
    public static void install(Path switchFile) {
        installed = new LinkFaults(switchFile);
        LOG.warn("link fault injection armed: {} switches it on (drop=SHARE,delay=MS) and off (empty)", switchFile);
    }

    /**
     * Parses {@code drop=0.2,delay=20}; blank is off.
     *
     * @throws IllegalArgumentException naming the part that is wrong
     */
    static Setting parse(String spec) {
        if (spec.isBlank()) {
            return Setting.OFF;
        }
        double drop = 0;
        int delay = 0;
        for (String part : spec.strip().split(",")) {
            String[] kv = part.strip().split("=", 2);
            if (kv.length != 2) {
                throw new IllegalArgumentException("link faults '" + spec + "': expected KEY=VALUE, got '" + part + "'");
            }
            try {
                switch (kv[0].strip().toLowerCase(Locale.ROOT)) {
                    case "drop" -> drop = Double.parseDouble(kv[1].strip());
                    case "delay" -> delay = Integer.parseInt(kv[1].strip());
                    default -> throw new IllegalArgumentException("link faults '" + spec + "': unknown key '" + kv[0]
                            + "' (drop, delay)");
                }
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("link faults '" + spec + "': '" + part + "' is not a number", e);
            }
        }
        return new Setting(drop, delay);
    }

    /** One call of a link. */
    interface Call {
        long deliver() throws org.fdnet.corba.idl.UnknownLink;
    }

    /** Whether an injector is installed in this process (on or off): calls must then go through {@link #deliver}. */
    static boolean armed() {
        return installed != null;
    }

    /** Makes {@code call}, through the injector when one is installed and on. */
    static long deliver(Call call) throws org.fdnet.corba.idl.UnknownLink {
        LinkFaults faults = installed;
        return faults == null ? call.deliver() : faults.inject(call);
    }

    private long inject(Call call) throws org.fdnet.corba.idl.UnknownLink {
        Setting now = current();
        if (!now.on()) {
            return call.deliver();
        }
        if (now.delayMillis() > 0) {
            try {
                Thread.sleep(now.delayMillis());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        double roll = ThreadLocalRandom.current().nextDouble();
        if (roll < now.dropShare() / 2) {
            throw new TRANSIENT("link fault injected: request dropped", 0, CompletionStatus.COMPLETED_NO);
        }
        long reply = call.deliver();
        if (roll < now.dropShare()) {
            throw new TRANSIENT("link fault injected: reply dropped", 0, CompletionStatus.COMPLETED_YES);
        }
        return reply;
    }

    private Setting current() {
        long now = System.currentTimeMillis();
        if (now - checkedAtMillis >= RECHECK_MILLIS) {
            checkedAtMillis = now;
            Setting before = setting;
            try {
                setting = parse(Files.readString(switchFile, StandardCharsets.UTF_8));
            } catch (NoSuchFileException e) {
                setting = Setting.OFF;
            } catch (IOException | IllegalArgumentException e) {
                LOG.warn("link faults: cannot use {} ({}); faults off", switchFile, e.getMessage());
                setting = Setting.OFF;
            }
            if (!setting.equals(before)) {
                LOG.warn("link faults now {}", setting.on() ? setting : "off");
            }
        }
        return setting;
    }
}
