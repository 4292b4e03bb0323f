/**
 * Where node classes come from, and the guard that nothing else is ever loaded.
 *
 * <pre>
 *   NodeInfo(class, path) ──▶ NodeClassResolver
 *        path empty: built-in package? (org.fdnet.runtime.library., org.fdnet.roq.; a bare name means the library)
 *        path given: real path under an allowed root? (the network file's folder, plus --allow-path roots)
 *                    ──▶ one URLClassLoader per path (parent: the runtime's loader, so the API is shared):
 *                        a jar; or a folder's classes and every jar directly in the folder
 *        ──▶ a Data or a Relation as the node's kind says, concrete, with a public no-argument constructor
 *   NodeClassResolver.nodeClassesOn(path): the concrete node classes a path offers (NodeClassScanner reads the
 *                    names; the classes are loaded, never initialised) ──▶ the editor's class choices
 *   any failure ──▶ NodeClassException: "module 'M', node 'N', class 'C': what is wrong and what to do"
 * </pre>
 */
package org.fdnet.runtime.loading;
