/**
 * A running network seen from outside: the {@link org.fdnet.control.LiveNetwork} seam that the editor's live
 * mode and deploy preview work against, whether the network runs in the same process
 * ({@link org.fdnet.control.LocalLiveNetwork}) or is reached through the control object it publishes over CORBA
 * ({@code org.fdnet.corba.control}).
 *
 * <pre>
 *   editor / preview ──apply(base, edited), load, hold, set, send──▶ LiveNetwork ──▶ Controller (one host)
 *                    ◀──changeSettled, valuesSampled, disconnected── LiveNetworkListener       or DistributedControl
 *
 *   apply(base, edited):  NetworkDiff.between(base, edited) ──entries()──▶ the preview's list of changes
 *                                                           ──asEdit()───▶ controller.apply (all or nothing;
 *                                                              refused, naming the conflict, when the running
 *                                                              definition no longer fits the difference)
 * </pre>
 */
package org.fdnet.control;
