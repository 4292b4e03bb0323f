/**
 * A running network seen from outside: the {@link org.fdnet.control.LiveNetwork} seam that the editor's live
 * mode and deploy preview work against, whether the network runs in the same process or is reached through
 * the control object it publishes over CORBA.
 *
 * <pre>
 *   editor / preview ──apply(base, edited), load, hold, set, send──▶ LiveNetwork ──▶ Controller (one host)
 *                    ◀──changeSettled, valuesSampled, disconnected── LiveNetworkListener       or DistributedControl
 * </pre>
 */
package org.fdnet.control;
