/**
 * Automatic layout with ELK layered: a network without .fdg is laid out whole; a node without a place
 * (new, or missing from the .fdg) is put where ELK would put it relative to its placed neighbours, so the
 * places the user set never move. A network of 300 nodes or more is laid out module by module: each module on
 * its own (in parallel), then the modules as blocks in the direction values flow between them.
 *
 * <pre>
 *  NetworkInfo ─▶ ElkLayeredLayout (ELK graph: nodes, Reader/Writer edges in the flow's direction)
 *                        │    └─▶ ModuleBlockLayout (large networks: a graph per module, then one of blocks)
 *                        │ positions
 *                        ▼
 *  NetworkLayout ◀── AutoPlacement (only nodes with no place)
 * </pre>
 */
package org.fdnet.hi.layout;
