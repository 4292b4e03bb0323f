package org.fdnet.logger.soak;

import java.io.PrintWriter;
import java.sql.SQLException;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;

/**
 * The soak's report on its network faults: one line per fault with what {@link NetworkFaultCheck} measured against its
 * bound, then one line per kind — injected, the longest detection, re-wiring and heal.
 */
final class NetworkFaultReport {
    private NetworkFaultReport() {
    }

    /** Prints nothing when no network fault was injected; whether every bound held. */
    static boolean print(PrintWriter out, long t0, List<InjectedFault> faults, NetworkFaultCheck check) throws SQLException {
        List<InjectedFault> network = faults.stream().filter(f -> f.kind().network).toList();
        if (network.isEmpty()) {
            return true;
        }
        out.println();
        out.printf("network faults (detected: after the injection, the run reporting the host LOST [<= %,d ms] or a"
                        + " host's logger away [<= %,d ms]; re-wired: after the heal, the run's \"host H is back\""
                        + " [<= %,d ms] or every host's logger connected [<= %,d ms]; healed: from the lift [<= %,d ms];"
                        + " longest link call [<= %,d ms];"
                        + " Relation stall: longest gap between Survey's values on the flyer [<= %,d ms]; held at most:"
                        + " link values waiting [<= %,d per link], logger events in memory [<= %,d], in the journal):%n",
                NetworkFaultCheck.HOST_DETECTION_MILLIS, NetworkFaultCheck.LOGGER_DETECTION_MILLIS,
                NetworkFaultCheck.HOST_REWIRE_MILLIS, NetworkFaultCheck.LOGGER_REWIRE_MILLIS, NetworkFaultCheck.HEAL_MILLIS,
                NetworkFaultCheck.CALL_MILLIS,
                NetworkFaultCheck.STALL_MILLIS, NetworkFaultCheck.LINK_VALUES, NetworkFaultCheck.CLIENT_EVENTS);
        boolean held = true;
        Map<FaultKind, long[]> perKind = new EnumMap<>(FaultKind.class); // injected, detected, re-wired, healed (max)
        for (InjectedFault f : network) {
            NetworkFaultCheck.Measured m = check.measure(f);
            boolean ok = m.boundsHeld(f.kind()) && f.healedMillis() >= 0
                    && f.healedMillis() <= NetworkFaultCheck.HEAL_MILLIS;
            held &= ok;
            out.printf("  [%6.1fs] %-16s %-10s %4d s  detected %s  re-wired %s  healed %s  call %,6d ms  stall %,6d ms"
                            + "  held %,d values, %,d events, journal %,d; dropped %d values, %d events  %s%n",
                    (f.atMillis() - t0) / 1e3, f.kind(), f.target(), (f.overMillis() - f.atMillis()) / 1000,
                    millis(m.detectedMillis()), millis(m.rewiredMillis()), millis(f.healedMillis()), m.longestCallMillis(),
                    m.stallMillis(), m.peakWaiting(), m.peakInMemory(), m.peakJournal(), m.linkValuesLost(),
                    m.eventsLost(), ok ? "ok" : "OVER A BOUND");
            long[] k = perKind.computeIfAbsent(f.kind(), x -> new long[] {0, -1, -1, -1});
            k[0]++;
            k[1] = Math.max(k[1], m.detectedMillis());
            k[2] = Math.max(k[2], m.rewiredMillis());
            k[3] = Math.max(k[3], f.healedMillis());
        }
        out.println();
        out.printf("  %-16s %8s %14s %14s %14s%n", "per kind", "injected", "detected max", "re-wired max", "healed max");
        perKind.forEach((kind, k) -> out.printf("  %-16s %8d %14s %14s %14s%n", kind, k[0], millis(k[1]), millis(k[2]),
                millis(k[3])));
        return held;
    }

    private static String millis(long ms) {
        return ms < 0 ? "-" : String.format("%,d ms", ms);
    }
}
