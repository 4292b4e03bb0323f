/**
 * The editor application: {@link org.fdnet.hi.app.HiWindow} with its File, Edit and View menus, the module
 * bar, search bar, node information panel and status bar, the read-only problem view of an invalid file,
 * saving, exporting and screenshots, and the Live menu (attach, collect and deploy, plot, save the running
 * network; the live machinery is {@link org.fdnet.hi.live}).
 *
 * <pre>
 *  X.fdn + X.fdg ─▶ OpenNetwork.load ─▶ UndoableNetworkEditor + GraphScene ─▶ HiWindow (canvas, panels)
 *        ▲                                   ▲ every edit (menus, panel, dialogs)
 *        └──────── OpenNetwork.saveAs ◀──────┘ File → Save (the .fdg keeps only nodes that exist)
 *  invalid X.fdn ─▶ Problem list ─▶ ProblemView (read-only, each problem jumps to its line:col)
 * </pre>
 */
package org.fdnet.hi.app;
