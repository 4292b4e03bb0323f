/**
 * The text-based editor (thesis Chapter 5 §IX): three frames that edit the network through forms, built on
 * SpeedyDesign ({@code org.fdnet.hi.speedy}) so that every widget stays consistent while the user types.
 *
 * <ul>
 *   <li>{@link org.fdnet.hi.text.NetworkFrame} — the network's name, its modules in numbers, add / edit /
 *       delete a module; opens a module's Basic frame.</li>
 *   <li>{@link org.fdnet.hi.text.BasicModuleFrame} — one module: name, load at start, its nodes and
 *       connections by name and in numbers, delete them; opens the Advanced frame.</li>
 *   <li>{@link org.fdnet.hi.text.AdvancedModuleFrame} — one module down to its entities: node tab (typing an
 *       existing name loads the node and turns Save into Update; the Data and Relation classes the network's
 *       paths hold; the parameter table with types; the parameters the class declares, with their descriptions,
 *       {@link org.fdnet.hi.text.DeclaredParametersTable}), connection tab (ends chosen among existing nodes only),
 *       rename with Merge/Replace ({@code org.fdnet.hi.merge}).</li>
 * </ul>
 *
 * Each frame is a thin Swing view over model classes holding the logic ({@link org.fdnet.hi.text.NetworkSummaryModel},
 * {@link org.fdnet.hi.text.ModuleFormModel}, {@link org.fdnet.hi.text.NodeFormModel},
 * {@link org.fdnet.hi.text.ConnectionFormModel}), which the tests drive headless.
 *
 * <pre>
 *   keystroke ─▶ view (QuietRefresh) ─▶ model.typeX() ─▶ SpeedyDesign.changed ─▶ model components update once,
 *                                                                               then the widgets depending on them
 *   Save/Delete/Add ─▶ model ─▶ NetworkEditor (one undoable edit) ─▶ NetworkInfo
 *   NetworkInfo change listener (any view's edit, undo, redo) ─▶ model "network" component ─▶ same cascade
 *   node class typed or chosen ─▶ NodeClasses (the run's class resolver under the network file's policy)
 *        ─▶ declared parameters, classes on the paths ─▶ node tab
 * </pre>
 *
 * Entry points for the application's menus (all modeless windows owned by {@code owner}; closing one stops it
 * listening to the network):
 * <pre>
 *   NetworkFrame.open(owner, editor)                       // or new NetworkFrame(owner, editor)
 *   BasicModuleFrame.open(owner, editor, "main")           // or new BasicModuleFrame(owner, editor, module)
 *   AdvancedModuleFrame.open(owner, editor, "main").showNode("Speed")
 * </pre>
 * A module frame whose module is renamed elsewhere follows it; when it is deleted the frame says so.
 */
package org.fdnet.hi.text;
