package org.fdnet.apart.cli;

import java.io.PrintWriter;
import java.util.List;
import org.fdnet.apart.ApartRig;

/** A rig's hosts, one line each: name, address, namespace and the faults on its link. */
final class RigTable {
    private RigTable() {
    }

    static void print(ApartRig rig, PrintWriter out) {
        out.printf("rig %s (process %d), %s:%n", rig.rigNamespace(), rig.ownerPid(), rig.subnet());
        out.printf("  %-16s %-15s %-32s %s%n", "host", "address", "namespace", "faults");
        for (String host : rig.hosts()) {
            out.printf("  %-16s %-15s %-32s %s%n", host, rig.address(host).getHostAddress(), rig.namespace(host),
                    faults(rig, host));
        }
    }

    private static String faults(ApartRig rig, String host) {
        List<String> tables = rig.faultTables(host).stream().map(t -> t.replace("fdnet_apart_", "")).toList();
        String queue = rig.queue(host);
        int rate = queue.indexOf(" rate ");
        String throttle = queue.contains("tbf") && rate >= 0
                ? "throttle " + queue.substring(rate + 6).split(" ")[0] : "";
        String all = String.join(", ", tables) + (tables.isEmpty() || throttle.isEmpty() ? "" : ", ") + throttle;
        return all.isEmpty() ? "none" : all;
    }
}
