/**
 * The simulator's benchmarks behind {@code fdnet bench rt|sim|roq}: the real-time loop against cyclictest, the
 * plant's step rate, and the RoQ network's reflex latency, push survival, heading drift and breakthrough sweeps.
 */
package org.fdnet.roq.bench;
