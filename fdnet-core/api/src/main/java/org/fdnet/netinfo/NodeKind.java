package org.fdnet.netinfo;

/** The two kinds of node of a flat network: values and the agents that compute them. */
public enum NodeKind {
    /** A value: a sensor reading, an intention, a posture. Declared by {@code dstructure}. */
    DATA("Data", "dstructure"),
    /** A processing agent that reads Datas and writes Datas. Declared by {@code pstructure}. */
    RELATION("Relation", "pstructure");

    private final String label;
    private final String element;

    NodeKind(String label, String element) {
        this.label = label;
        this.element = element;
    }

    /**
     * The word users see: "Data" or "Relation".
     *
     * @return {@code Data} or {@code Relation}
     */
    public String label() {
        return label;
    }

    /**
     * The .fdn element that declares a node of this kind.
     *
     * @return {@code dstructure} or {@code pstructure}
     */
    public String element() {
        return element;
    }
}
