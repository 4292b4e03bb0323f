/**
 * The editor application: {@link org.fdnet.hi.app.HiWindow} with its File, Edit and View menus, the module
 * bar, search bar, node information panel and status bar, the read-only problem view of an invalid file,
 * and saving, exporting and screenshots.
 *
 * <pre>
 *  X.fdn + X.fdg ─▶ OpenNetwork.load ─▶ UndoableNetworkEditor + GraphScene ─▶ HiWindow (canvas, panels)
 *        ▲                                   ▲ every edit (menus, panel, dialogs)
 *        └──────── OpenNetwork.saveAs ◀──────┘ File → Save (the .fdg keeps only nodes that exist)
 *  invalid X.fdn ─▶ Problem list ─▶ ProblemView (read-only, each problem jumps to its line:col)
 * </pre>
 */
package org.fdnet.hi.app;
