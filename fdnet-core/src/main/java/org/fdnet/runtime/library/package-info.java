/**
 * The built-in node classes: Datas of every value type (and sensor Datas fed from outside), and the
 * Relations of {@code docs/reference/relations.md}. A node names them with an empty {@code path} and either the
 * fully qualified name or the bare class name.
 *
 * <pre>
 *   sources     PeriodicSource, Constant                     ──▶ Datas
 *   shaping     Expression, MovingAverage, LowPass, RateLimiter, Threshold
 *   deciding    Integration (candidates × judgment, thesis Figure 5), Selector, PdController
 *   watching    Print;  AutoFilter (self-organization through the Servants)
 *   messages    ExpressionServant (offers a servant), ServantAsker (messages one; replies become values)
 * </pre>
 */
package org.fdnet.runtime.library;
