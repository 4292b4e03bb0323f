/**
 * Automatic layout with ELK layered: a network without .fdg is laid out whole; a node without a place
 * (new, or missing from the .fdg) is put where ELK would put it relative to its placed neighbours, so the
 * places the user set never move.
 *
 * <pre>
 *  NetworkInfo ─▶ ElkLayeredLayout (ELK graph: nodes, Reader/Writer edges in the flow's direction)
 *                        │ positions
 *                        ▼
 *  NetworkLayout ◀── AutoPlacement (only nodes with no place)
 * </pre>
 */
package org.fdnet.hi.layout;
