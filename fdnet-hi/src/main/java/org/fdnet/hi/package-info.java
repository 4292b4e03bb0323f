/**
 * The Human Interface: the graphical and text-based network editor ({@code fdnet hi}). Packages by
 * component: {@code edit} (the undoable editor every view edits through), {@code graph} (the graphic
 * panel), {@code layout} (automatic layout with ELK), {@code app} (the window, menus and panels),
 * {@code cli} (the commands and the benchmark).
 */
package org.fdnet.hi;
