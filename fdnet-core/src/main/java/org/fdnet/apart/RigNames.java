package org.fdnet.apart;

import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The names of what one rig makes: its own namespace {@code PREFIX-PID} (the bridge) and one namespace
 * {@code PREFIX-PID-HOST} per host. The owning process's id in every name lets a later rig recognise the leftovers
 * of one that was killed before it could clean up ({@link ApartRig#sweep}).
 *
 * @param prefix what every name starts with: a letter, then letters, digits or '_' (no '-', so the id that follows
 *               is unambiguous)
 * @param pid    the process that owns the rig
 */
record RigNames(String prefix, long pid) {
    private static final Pattern PREFIX = Pattern.compile("[A-Za-z][A-Za-z0-9_]{0,15}");
    private static final Pattern HOST = Pattern.compile("[A-Za-z0-9][A-Za-z0-9_.-]{0,31}");

    RigNames {
        requirePrefix(prefix);
    }

    /** The namespace that holds the bridge every host's link is joined to. */
    String rigNamespace() {
        return prefix + "-" + pid;
    }

    /** The namespace host {@code host} runs in. */
    String hostNamespace(String host) {
        return rigNamespace() + "-" + host;
    }

    /**
     * The process that owns {@code namespace}, when it is one a rig with {@code prefix} made.
     *
     * @return the owner's id; empty for any other namespace
     */
    static Optional<Long> ownerOf(String prefix, String namespace) {
        Matcher m = Pattern.compile(Pattern.quote(prefix) + "-([0-9]+)(?:-.+)?").matcher(namespace);
        return m.matches() ? Optional.of(Long.parseLong(m.group(1))) : Optional.empty();
    }

    /** @throws IllegalArgumentException when {@code prefix} is not a letter followed by letters, digits or '_' */
    static void requirePrefix(String prefix) {
        if (prefix == null || !PREFIX.matcher(prefix).matches()) {
            throw new IllegalArgumentException("rig prefix '" + prefix + "' must be a letter followed by at most 15"
                    + " letters, digits or '_'");
        }
    }

    /** @throws IllegalArgumentException when {@code host} cannot name a namespace */
    static void requireHost(String host) {
        if (host == null || !HOST.matcher(host).matches()) {
            throw new IllegalArgumentException("host name '" + host + "' must be 1 to 32 letters, digits, '.', '_' or"
                    + " '-', starting with a letter or digit");
        }
    }
}
