package org.fdnet.logger.bench;

import java.util.Arrays;

/** The sizes of the batches the writer committed, in order (for a baseline cut the same way). */
final class BatchSizes {
    private int[] sizes = new int[1024];
    private int count;
    private long total;
    private int largest;

    synchronized void add(int size) {
        if (count == sizes.length) {
            sizes = Arrays.copyOf(sizes, count * 2);
        }
        sizes[count++] = size;
        total += size;
        largest = Math.max(largest, size);
    }

    synchronized int count() {
        return count;
    }

    synchronized double mean() {
        return count == 0 ? 0 : (double) total / count;
    }

    synchronized int largest() {
        return largest;
    }

    synchronized int[] toArray() {
        return count == 0 ? new int[] {1000} : Arrays.copyOf(sizes, count);
    }
}
