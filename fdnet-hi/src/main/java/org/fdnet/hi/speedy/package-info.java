/**
 * SpeedyDesign (thesis Chapter 5 §X): one component handler through which the components of a frame learn
 * that another changed, so that each component's state is set in one place — its own {@code update()} — and
 * each updates exactly once per change, parents before children.
 *
 * <pre>
 *   component changes itself ─▶ SpeedyDesign.changed(it) ─▶ its descendants, by level ─▶ each update() once
 * </pre>
 *
 * The text-based frames ({@code org.fdnet.hi.text}) are built on it.
 */
package org.fdnet.hi.speedy;
