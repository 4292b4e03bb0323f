package org.fdnet.corba.bench;

import java.lang.management.ManagementFactory;
import java.time.Duration;

/**
 * CPU time used so far by this JVM and by bench-b's JVM, so a phase of the benchmark can say what it cost
 * in CPU beside what it took in wall time: {@link #since} gives the CPU per second of wall time (1.0 = one
 * whole core busy). bench-b's time comes from the operating system ({@code /proc} on Linux), in clock
 * ticks of 10 ms: phases last seconds, so that is fine.
 */
final class CpuClock {
    private final long childPid;

    CpuClock(long childPid) {
        this.childPid = childPid;
    }

    /** A reading: wall, this JVM's CPU and bench-b's CPU, in ns. */
    record Reading(long wallNanos, long thisJvmNanos, long childNanos) {
    }

    /** CPU used in a phase, in cores (CPU seconds per wall second). */
    record Usage(double thisJvmCores, double childCores) {
        double totalCores() {
            return thisJvmCores + childCores;
        }
    }

    Reading now() {
        long own = ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean()).getProcessCpuTime();
        long child = ProcessHandle.of(childPid).flatMap(h -> h.info().totalCpuDuration()).map(Duration::toNanos)
                .orElseThrow(() -> new IllegalStateException("cannot read the CPU time of bench-b (pid " + childPid + ")"));
        return new Reading(System.nanoTime(), own, child);
    }

    Usage since(Reading start) {
        Reading end = now();
        double wall = end.wallNanos() - start.wallNanos();
        return new Usage((end.thisJvmNanos() - start.thisJvmNanos()) / wall, (end.childNanos() - start.childNanos()) / wall);
    }
}
