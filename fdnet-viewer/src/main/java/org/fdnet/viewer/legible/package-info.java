/**
 * Every name legible: the windows (editor, viewer, demo) show node and module names in whatever script the
 * network uses — the thesis's lab wrote Japanese names in EUC-JP. {@link org.fdnet.viewer.legible.LegibleFont}
 * picks, for the names a window shows, a font that can draw them all ({@link java.awt.Font#canDisplayUpTo}),
 * and when no installed font can, gives the one message for the status bar naming the package to install.
 *
 * <pre>
 *   names ─▶ LegibleFont.forNames(preferred, names) ─▶ Choice(font, warning)
 *              preferred draws all? ─yes─▶ preferred
 *              else an installed family that does (Noto Sans CJK, IPAGothic first) ─▶ that family, same style/size
 *              else preferred + "install fonts-noto-cjk" warning (shown once per window)
 * </pre>
 * fdnet-hi and roq-sim depend on fdnet-viewer, so the one copy of this lives here.
 */
package org.fdnet.viewer.legible;
