/**
 * The RoQ simulator: a JNI real-time joint loop driving a simulated TITAN-VIII quadruped. Part 5 of the
 * plan fills this module; it holds no code yet and nothing here claims to work.
 */
package org.fdnet.roq;
