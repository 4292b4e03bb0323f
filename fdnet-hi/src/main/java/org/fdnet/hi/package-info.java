/**
 * The Human Interface: the graphical and text-based network editor ({@code fdnet hi}). Packages by
 * component: {@code edit} (the undoable editor every view edits through), {@code graph} (the graphic
 * panel), {@code layout} (automatic layout with ELK), {@code text} (the text frames, on {@code speedy}),
 * {@code merge} (the Merge/Replace dialog), {@code live} (editing a running network), {@code app} (the window,
 * menus and panels), {@code cli} (the command; {@code fdnet bench hi} is fdnet-hi/bench's).
 */
package org.fdnet.hi;
