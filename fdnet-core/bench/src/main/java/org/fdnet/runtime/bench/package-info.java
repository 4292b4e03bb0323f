/**
 * {@code fdnet bench core}: the runtime's in-process costs beside plain Java doing the same work.
 *
 * <pre>
 *   hop:     D0 ──▶ Relay(+1) ──▶ D1 ──▶ observer        vs  Cell ──▶ lambda(+1) ──▶ Cell ──▶ observer
 *   chain:   D0 ──▶ R1 ──▶ D1 … R10 ──▶ D10               vs  ten such lambdas
 *   fan-out: In ──▶ R0..R99 ──▶ Out0..Out99                vs  a loop over 100 lambdas
 * </pre>
 */
package org.fdnet.runtime.bench;
