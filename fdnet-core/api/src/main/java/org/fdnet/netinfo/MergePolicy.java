package org.fdnet.netinfo;

/** Which parameters the node produced by {@link NetworkInfo#mergeNodes} keeps. */
public enum MergePolicy {
    /** The first node's parameters only. */
    FIRST,
    /** The second node's parameters only. */
    SECOND,
    /** The first node's parameters, then those of the second that the first does not already have. */
    BOTH
}
