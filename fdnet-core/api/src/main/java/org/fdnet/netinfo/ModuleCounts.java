package org.fdnet.netinfo;

/** A module in numbers, as the thesis's text-based display shows it. */
public record ModuleCounts(int datas, int relations, int readers, int writers) {
    public int nodes() {
        return datas + relations;
    }

    public int connections() {
        return readers + writers;
    }

    public ModuleCounts plus(ModuleCounts other) {
        return new ModuleCounts(datas + other.datas, relations + other.relations,
                readers + other.readers, writers + other.writers);
    }
}
