package org.fdnet.apart.cli;

import java.io.PrintWriter;
import org.fdnet.apart.ApartRig;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code fdnet apart fault}: puts a fault on a host's link, or lifts it. */
@Command(name = "fault", mixinStandardHelpOptions = true,
        description = "Put a fault on HOST's link, or lift it: blackhole, heal, loss PERCENT, throttle KBIT, clear.",
        footer = {"", "Faults:",
                "  blackhole        drop every packet in and out, silently (no reset): a pulled cable",
                "  heal             lift blackhole",
                "  loss PERCENT     drop each packet in or out with this probability (0 lifts it)",
                "  throttle KBIT    limit the link to KBIT kbit/s each way",
                "  clear            lift every fault"})
public final class ApartFaultCommand extends OnTheRigThatIsUp {
    @Parameters(index = "0", paramLabel = "HOST", description = "the host whose link gets the fault")
    String host;

    @Parameters(index = "1", paramLabel = "FAULT", description = "blackhole, heal, loss, throttle or clear")
    String fault;

    @Parameters(index = "2", arity = "0..1", paramLabel = "VALUE", description = "loss's PERCENT, throttle's KBIT")
    Integer value;

    @Override
    int on(ApartRig rig, PrintWriter out) {
        out.println("ok: " + host + " " + apply(rig));
        return 0;
    }

    private String apply(ApartRig rig) {
        switch (fault) {
            case "blackhole" -> {
                rig.blackhole(host);
                return "black-holed: every packet in and out is dropped silently";
            }
            case "heal" -> {
                rig.heal(host);
                return "healed";
            }
            case "loss" -> {
                rig.loss(host, required("PERCENT"));
                return value == 0 ? "loses nothing" : "loses " + value + " % of packets each way";
            }
            case "throttle" -> {
                rig.throttle(host, required("KBIT"));
                return "throttled to " + value + " kbit/s each way";
            }
            case "clear" -> {
                rig.clear(host);
                return "cleared: no fault on its link";
            }
            default -> throw new IllegalArgumentException("unknown fault '" + fault + "'; give blackhole, heal, loss PERCENT,"
                    + " throttle KBIT or clear");
        }
    }

    private int required(String what) {
        if (value == null) {
            throw new IllegalArgumentException(fault + " needs " + what);
        }
        return value;
    }
}
