/**
 * The RoQ: the simulated robot ({@code org.fdnet.roq.sim}), its Java2D view ({@code org.fdnet.roq.view}) and, from
 * Part 6, its FDNet Data and Relation nodes and the bridge between a running network and the simulator.
 */
package org.fdnet.roq;
