package org.fdnet.corba;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/**
 * Keeps every CPU of this machine out of its deep idle states while held: Linux's PM QoS request through
 * {@code /dev/cpu_dma_latency}, a wake-up latency of 0 µs, which stands for as long as the file stays open (closing
 * it, or the process ending, lets the CPUs sleep again). A thread woken on an idle core then runs within
 * microseconds instead of tens of them — on a virtual machine whose idle vCPUs halt, a cross-host round trip about
 * halves — at the price of cores that poll instead of sleeping. Needs root.
 */
public final class CpuLatencyHold implements AutoCloseable {
    /** The kernel's PM QoS interface for the CPUs' wake-up latency. */
    static final Path DEVICE = Path.of("/dev/cpu_dma_latency");

    private final FileChannel request;

    private CpuLatencyHold(FileChannel request) {
        this.request = request;
    }

    /**
     * Holds the wake-up latency at 0 µs until {@link #close}.
     *
     * @throws IllegalStateException naming the device and why, when it cannot be held (not root, no such device)
     */
    public static CpuLatencyHold hold() {
        FileChannel channel = null;
        try {
            channel = FileChannel.open(DEVICE, StandardOpenOption.WRITE);
            channel.write(ByteBuffer.allocate(Integer.BYTES).order(ByteOrder.nativeOrder()).putInt(0).flip());
            return new CpuLatencyHold(channel);
        } catch (IOException | SecurityException e) {
            closeQuietly(channel);
            throw new IllegalStateException("cannot hold the CPUs' wake-up latency at 0 µs through " + DEVICE + ": "
                    + e + " (it needs root)", e);
        }
    }

    /** The wake-up latency the CPUs keep now, in µs: the least any process asks for (2,000,000,000: none asked). */
    public static long current() {
        try (FileChannel channel = FileChannel.open(DEVICE, StandardOpenOption.READ)) {
            ByteBuffer value = ByteBuffer.allocate(Integer.BYTES).order(ByteOrder.nativeOrder());
            while (value.hasRemaining() && channel.read(value) >= 0) {
                // a 4-byte read
            }
            return value.flip().getInt();
        } catch (IOException | SecurityException e) {
            throw new IllegalStateException("cannot read " + DEVICE + ": " + e, e);
        }
    }

    /** Lets the CPUs sleep again (as far as no other process holds them). */
    @Override
    public void close() {
        closeQuietly(request);
    }

    private static void closeQuietly(FileChannel channel) {
        if (channel != null) {
            try {
                channel.close();
            } catch (IOException e) {
                // the kernel drops the request with the file either way
            }
        }
    }
}
