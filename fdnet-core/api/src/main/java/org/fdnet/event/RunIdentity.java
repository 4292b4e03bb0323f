package org.fdnet.event;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.List;
import java.util.Objects;
import java.util.UUID;

/**
 * What one run of a network is, decided once by the process that runs it ({@code fdnet run}, the editor's
 * Run): its id, the network's name, the {@code .fdn} text as it was deployed and that text's SHA-256, when it
 * started (µs since the epoch) and the hosts it runs on. The coordinator hands it to every host at deployment;
 * each host's events are recorded under it, so one network run is one run in the logger however many
 * processes record it.
 *
 * @param id            the run's id, random
 * @param network       the network's name
 * @param definition    the {@code .fdn} text as deployed
 * @param sha256        the hexadecimal SHA-256 of {@code definition}'s UTF-8 bytes
 * @param startedMicros when the run started, µs since the epoch
 * @param hosts         the hosts it runs on
 */
public record RunIdentity(UUID id, String network, String definition, String sha256, long startedMicros,
                          List<String> hosts) {
    /**
     * Checks the parts and copies the hosts.
     *
     * @param id            the run's id
     * @param network       the network's name
     * @param definition    the {@code .fdn} text as deployed
     * @param sha256        that text's SHA-256, hexadecimal
     * @param startedMicros when the run started, µs since the epoch
     * @param hosts         the hosts it runs on, copied
     * @throws NullPointerException when a part is null
     */
    public RunIdentity {
        Objects.requireNonNull(id, "id");
        Objects.requireNonNull(network, "network");
        Objects.requireNonNull(definition, "definition");
        Objects.requireNonNull(sha256, "sha256");
        hosts = List.copyOf(hosts);
    }

    /**
     * A new run of {@code network}, started now, whose definition is {@code definitionText}.
     *
     * @param network        the network's name
     * @param definitionText the {@code .fdn} text being deployed
     * @param hosts          the hosts it runs on
     * @return a run with a fresh random id and the wall clock's time
     */
    public static RunIdentity start(String network, String definitionText, List<String> hosts) {
        return new RunIdentity(UUID.randomUUID(), network, definitionText, sha256Of(definitionText),
                System.currentTimeMillis() * 1000, hosts);
    }

    /**
     * The hexadecimal SHA-256 of {@code text}'s UTF-8 bytes.
     *
     * @param text any text
     * @return 64 lower-case hexadecimal digits
     */
    public static String sha256Of(String text) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256")
                    .digest(text.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("this JVM has no SHA-256", e);
        }
    }
}
