package org.fdnet.apart;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.corba.FdnetChildProcess;

/**
 * An apart rig and the {@code fdnet} processes a test started on its hosts, each with the test's own home (their logs
 * and journals stay out of the user's ~/.fdnet). Closing stops the processes, the last started first, then removes
 * the rig.
 */
final class ApartProcesses implements AutoCloseable {
    private final ApartRig rig;
    private final List<String> jvmOptions;
    private final List<FdnetChildProcess> processes = new ArrayList<>();

    private ApartProcesses(ApartRig rig, Path home) {
        this.rig = rig;
        this.jvmOptions = List.of("-Duser.home=" + home);
    }

    /** A rig of {@code hosts} (needs root: {@link ApartRig#create} throws its one line otherwise). */
    static ApartProcesses create(String prefix, List<String> hosts, Path home) {
        return new ApartProcesses(ApartRig.create(prefix, hosts), home);
    }

    ApartRig rig() {
        return rig;
    }

    /** The JVM options every process gets: the test's home. */
    List<String> jvmOptions() {
        return jvmOptions;
    }

    /** {@code host}'s address inside the rig, as text. */
    String address(String host) {
        return rig.address(host).getHostAddress();
    }

    /** Starts {@code fdnet ARGS...} on {@code host} and waits for {@code ready} in its output; stopped on close. */
    FdnetChildProcess start(String label, String host, List<String> args, String ready, long readyMillis) {
        return add(FdnetChildProcess.start(label, rig.command(host, List.of()), jvmOptions, args, ready, readyMillis));
    }

    /** A process started otherwise, stopped on close too. */
    synchronized FdnetChildProcess add(FdnetChildProcess p) {
        processes.add(p);
        return p;
    }

    @Override
    public void close() {
        List<FdnetChildProcess> started;
        synchronized (this) {
            started = new ArrayList<>(processes);
        }
        try {
            for (int i = started.size() - 1; i >= 0; i--) {
                started.get(i).close();
            }
        } finally {
            rig.close();
        }
    }
}
