package org.fdnet.corba.cli;

import java.io.PrintWriter;
import org.fdnet.control.LiveNetwork;
import org.fdnet.corba.OrbSettings;
import org.fdnet.corba.control.ControlPublication;
import picocli.CommandLine.Option;

/**
 * Where a run in this process publishes its control object ({@code fdnet run}, {@code fdnet demo}): a port on
 * 127.0.0.1 by default. A distributed run registers it in its naming service instead.
 */
public final class ControlOptions {
    @Option(names = "--control-port", paramLabel = "PORT",
            description = "port of the network's control object (default: a free port; the address is written to"
                    + " ~/.fdnet/run/NAME.ref for fdnet control NAME and fdnet hi --attach NAME)")
    int port;

    @Option(names = "--control-host", paramLabel = "ADDR",
            description = "address the control object listens on (default: ${DEFAULT-VALUE}); anyone who reaches it"
                    + " can change the running network", defaultValue = OrbSettings.LOOPBACK)
    String host = OrbSettings.LOOPBACK;

    @Option(names = "--no-control", description = "do not publish the control object")
    boolean off;

    /** Whether {@code --no-control} was given. */
    public boolean off() {
        return off;
    }

    /** The option that places the control object at a port or address, if given ({@code null}: neither). */
    public String placement() {
        if (port != 0) {
            return "--control-port";
        }
        return OrbSettings.LOOPBACK.equals(host) ? null : "--control-host";
    }

    /**
     * Publishes {@code network} and prints where; {@code null} with {@code --no-control}.
     *
     * @throws IllegalArgumentException naming the option when it cannot be published there
     */
    /** The address the control object listens on. */
    public String host() {
        return host;
    }

    public ControlPublication publish(LiveNetwork network, PrintWriter out) {
        if (off) {
            return null;
        }
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("--control-port must be 0..65535, was " + port);
        }
        try {
            ControlPublication p = ControlPublication.atPort(network, host, port);
            out.println(p.announcement());
            out.flush();
            return p;
        } catch (IllegalStateException e) {
            throw new IllegalArgumentException("--control-host " + host + " --control-port " + port + ": "
                    + e.getMessage(), e);
        }
    }
}
