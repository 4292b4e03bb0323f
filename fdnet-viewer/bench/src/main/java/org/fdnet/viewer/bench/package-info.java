/**
 * The viewer's benchmark behind {@code fdnet bench viewer}: plot refresh and history queries, each beside its
 * same-run baseline.
 */
package org.fdnet.viewer.bench;
