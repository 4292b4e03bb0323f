package org.fdnet.logger.soak;

import java.sql.SQLException;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fdnet.corba.DistributedRun;
import org.fdnet.corba.HostHealth;
import org.fdnet.corba.LinkSettings;
import org.fdnet.corba.OrbSettings;
import org.fdnet.corba.OutboundLink;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.netinfo.NodeRef;

/**
 * What one network fault cost, measured against the bounds FDNet's settings promise:
 * <ul>
 *   <li><b>detected</b> — a black-holed host reported lost by the run ({@code host H LOST}), or the logger reported
 *       away by a host's health line, after the injection: within {@link #HOST_DETECTION_MILLIS} and
 *       {@link #LOGGER_DETECTION_MILLIS};</li>
 *   <li><b>re-wired</b> — after the heal, the run's {@code host H is back}, or every host's logger connected again:
 *       within {@link #HOST_REWIRE_MILLIS} and {@link #LOGGER_REWIRE_MILLIS};</li>
 *   <li><b>healed</b> — from the lift until a value acknowledged after it is stored end to end: within
 *       {@link #HEAL_MILLIS};</li>
 *   <li><b>longest call</b> — the longest {@code deliver} call of any host's link while the fault lasted (and its
 *       settling time after): a link's caller is blocked at most the ORB's call timeout ({@link #CALL_MILLIS});</li>
 *   <li><b>Relation stall</b> — the longest gap between two values of {@code main/Map}, which {@code Survey} writes
 *       every 100 ms on the flyer: a Relation's thread is blocked at most while its link's ring is full
 *       ({@link #STALL_MILLIS});</li>
 *   <li><b>held</b> — the most link values waiting for a peer and logger events in a client's memory, by the hosts'
 *       health lines: bounded by the links' capacity and the client's {@code memoryEvents}; none dropped.</li>
 * </ul>
 */
final class NetworkFaultCheck {
    private static final long SLACK_MILLIS = 1_500; // a loaded machine's scheduling, and the 1 s of a health line
    static final long CALL_MILLIS = OrbSettings.defaults().callTimeoutMillis() + SLACK_MILLIS;
    static final long HOST_DETECTION_MILLIS = DistributedRun.HOST_PING_MILLIS + OrbSettings.defaults().callTimeoutMillis()
            + SLACK_MILLIS;
    static final long HOST_REWIRE_MILLIS = HOST_DETECTION_MILLIS;
    private static final LoggerClientSettings CLIENT = LoggerClientSettings.defaults("logger", 1, "soak");
    static final long LOGGER_DETECTION_MILLIS = CLIENT.silenceTimeout().toMillis() + SLACK_MILLIS;
    /** A connect begun during the partition runs out first, then the client waits its reconnect delay. */
    static final long LOGGER_REWIRE_MILLIS = 5_000 + CLIENT.reconnectDelay().toMillis() + SLACK_MILLIS;
    /**
     * From a network fault's lift until a value sent after it is stored end to end: the slower re-wiring (the logger's)
     * plus the logger's commit and the soak's poll of the database.
     */
    static final long HEAL_MILLIS = LOGGER_REWIRE_MILLIS + 5_000;
    static final long SURVEY_PERIOD_MILLIS = 100;
    static final long STALL_MILLIS = SURVEY_PERIOD_MILLIS + OutboundLink.MAX_WRITER_WAIT_MILLIS + SLACK_MILLIS;
    static final long LINK_VALUES = LinkSettings.defaults().capacity();
    static final long CLIENT_EVENTS = CLIENT.memoryEvents();
    /** Measured until this long after the heal, so what the heal sets off is seen too. */
    private static final long SETTLE_MILLIS = 8_000;
    private static final NodeRef SURVEYED = new NodeRef("main", "Map");
    private static final Pattern HEALTH = Pattern.compile("fdnet host (\\S+)" + Pattern.quote(HostHealth.MARK)
            + "links (\\d+), waiting (\\d+), lost (\\d+), longest call (\\d+) ms; logger (\\w+)(?:, in memory (\\d+),"
            + " journal (\\d+), lost (\\d+))?");

    /** What was measured; -1 where a figure does not apply or never came. */
    record Measured(long detectedMillis, long rewiredMillis, long longestCallMillis, long stallMillis,
                    long peakWaiting, long peakInMemory, long peakJournal, long linkValuesLost, long eventsLost) {
        boolean detectionWithin(FaultKind kind) {
            return switch (kind) {
                case HOST_PARTITION -> detectedMillis >= 0 && detectedMillis <= HOST_DETECTION_MILLIS;
                case LOGGER_PARTITION -> detectedMillis >= 0 && detectedMillis <= LOGGER_DETECTION_MILLIS;
                default -> true;
            };
        }

        boolean rewireWithin(FaultKind kind) {
            return switch (kind) {
                case HOST_PARTITION -> rewiredMillis >= 0 && rewiredMillis <= HOST_REWIRE_MILLIS;
                case LOGGER_PARTITION -> rewiredMillis >= 0 && rewiredMillis <= LOGGER_REWIRE_MILLIS;
                default -> true;
            };
        }

        boolean boundsHeld(FaultKind kind) {
            return detectionWithin(kind) && rewireWithin(kind) && longestCallMillis <= CALL_MILLIS
                    && stallMillis >= 0 && stallMillis <= STALL_MILLIS && peakWaiting <= LINK_VALUES
                    && peakInMemory <= CLIENT_EVENTS && linkValuesLost == 0 && eventsLost == 0;
        }
    }

    private final OutputWatch output;
    private final SoakDatabase database;

    NetworkFaultCheck(OutputWatch output, SoakDatabase database) {
        this.output = output;
        this.database = database;
    }

    Measured measure(InjectedFault f) throws SQLException {
        long until = f.overMillis() + SETTLE_MILLIS;
        long detected = -1;
        long rewired = -1;
        if (f.kind() == FaultKind.HOST_PARTITION) {
            detected = firstAfter(f.atMillis(), "run", "host " + f.target() + " LOST");
            long back = firstAfter(f.atMillis(), "run", "host " + f.target() + " is back");
            rewired = back < 0 ? -1 : Math.max(0, f.atMillis() + back - f.overMillis());
        }
        List<OutputWatch.Line> health = output.between(f.atMillis(), until, l -> l.text().contains(HostHealth.MARK));
        if (f.kind() == FaultKind.LOGGER_PARTITION) {
            detected = health.stream().filter(l -> l.text().contains("logger away")).mapToLong(l -> l.atMillis() - f.atMillis())
                    .min().orElse(-1);
            rewired = loggerBackMillis(f);
        }
        long longestCall = 0;
        long waiting = 0;
        long inMemory = 0;
        long journal = 0;
        long linkLost = 0;
        long eventsLost = 0;
        for (OutputWatch.Line l : health) {
            Matcher m = HEALTH.matcher(l.text());
            if (!m.find()) {
                continue;
            }
            waiting = Math.max(waiting, Long.parseLong(m.group(3)));
            linkLost = Math.max(linkLost, Long.parseLong(m.group(4)));
            longestCall = Math.max(longestCall, Long.parseLong(m.group(5)));
            if (m.group(7) != null) {
                inMemory = Math.max(inMemory, Long.parseLong(m.group(7)));
                journal = Math.max(journal, Long.parseLong(m.group(8)));
                eventsLost = Math.max(eventsLost, Long.parseLong(m.group(9)));
            }
        }
        long stall = database.longestGapMillis(SURVEYED, f.atMillis(), until);
        return new Measured(detected, rewired, longestCall, stall, waiting, inMemory, journal, linkLost, eventsLost);
    }

    /** After the heal: when the last host's health line said its logger was connected again. */
    private long loggerBackMillis(InjectedFault f) {
        long latest = -1;
        for (String host : List.of("flyer", "crawler")) {
            long back = output.between(f.overMillis(), f.overMillis() + 60_000, l -> l.process().equals(host)
                    && l.text().contains(HostHealth.MARK) && l.text().contains("logger connected")).stream()
                    .mapToLong(OutputWatch.Line::atMillis).min().orElse(-1);
            if (back < 0) {
                return -1;
            }
            latest = Math.max(latest, back - f.overMillis());
        }
        return latest;
    }

    private long firstAfter(long fromMillis, String process, String text) {
        return output.between(fromMillis, fromMillis + 600_000, l -> l.process().equals(process) && l.text().contains(text))
                .stream().mapToLong(l -> l.atMillis() - fromMillis).findFirst().orElse(-1);
    }
}
