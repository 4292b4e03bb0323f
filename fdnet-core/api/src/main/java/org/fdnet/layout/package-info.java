/**
 * View state of a network: what the .fdg side file holds and the editor draws.
 *
 * <pre>
 *   X.fdg ──LayoutRepository──▶ NetworkLayout ── modules ──▶ ModuleLayout (colour, visible)
 *                                                              └── nodes ──▶ NodeLayout (x, y, size, colour)
 *   X.fdn ──NetworkRepository─▶ NetworkInfo   (never holds any of this)
 * </pre>
 *
 * Keys are module and node names, so a layout survives any edit that keeps names; entries for nodes
 * that no longer exist are reported by {@link org.fdnet.layout.NetworkLayout#staleEntries} and are harmless.
 */
package org.fdnet.layout;
