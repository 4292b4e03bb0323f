package org.fdnet.netinfo;

/** A connection always joins one Data and one Relation; its kind says which way the value flows. */
public enum ConnectionKind {
    /** The Relation reads the Data: value flows Data to Relation. Element {@code read}. */
    READER("Reader", "read"),
    /** The Relation writes the Data: value flows Relation to Data. Element {@code write}. */
    WRITER("Writer", "write");

    private final String label;
    private final String element;

    ConnectionKind(String label, String element) {
        this.label = label;
        this.element = element;
    }

    /**
     * The word users read in messages and the editor.
     *
     * @return {@code Reader} or {@code Writer}
     */
    public String label() {
        return label;
    }

    /**
     * The XML element of a {@code .fdn} file that declares such a connection.
     *
     * @return {@code read} or {@code write}
     */
    public String element() {
        return element;
    }
}
