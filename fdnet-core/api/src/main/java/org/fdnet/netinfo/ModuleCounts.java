package org.fdnet.netinfo;

/**
 * A module in numbers, as the thesis's text-based display shows it.
 *
 * @param datas     the number of Data nodes
 * @param relations the number of Relation nodes
 * @param readers   the number of Reader connections the module declares
 * @param writers   the number of Writer connections the module declares
 */
public record ModuleCounts(int datas, int relations, int readers, int writers) {
    /**
     * Datas and Relations together.
     *
     * @return the number of nodes
     */
    public int nodes() {
        return datas + relations;
    }

    /**
     * Readers and Writers together.
     *
     * @return the number of connections
     */
    public int connections() {
        return readers + writers;
    }

    /**
     * The sum of two counts, e.g. of a network's modules.
     *
     * @param other the counts to add
     * @return a new count, field by field
     */
    public ModuleCounts plus(ModuleCounts other) {
        return new ModuleCounts(datas + other.datas, relations + other.relations,
                readers + other.readers, writers + other.writers);
    }
}
