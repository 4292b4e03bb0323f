package org.fdnet.testing;

import java.awt.Component;
import java.awt.Container;
import java.awt.Rectangle;
import java.awt.Window;
import java.util.ArrayList;
import java.util.List;
import javax.swing.AbstractButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JRootPane;
import javax.swing.JScrollBar;
import javax.swing.JScrollPane;
import javax.swing.JViewport;
import javax.swing.Scrollable;
import javax.swing.plaf.basic.BasicSplitPaneDivider;
import javax.swing.JSlider;
import javax.swing.JSpinner;
import javax.swing.JTabbedPane;
import javax.swing.JTable;
import javax.swing.JTree;
import javax.swing.SwingUtilities;
import javax.swing.text.JTextComponent;

/**
 * What a person sees of a window, checked as a test: every input component (text fields, buttons, check boxes,
 * combo boxes, spinners, sliders, lists, tables, trees) is showing, has a size, and lies wholly inside the window's
 * visible area and inside every scroll pane's view around it; no label, button, table cell or column title shows
 * its text cut with an ellipsis, and no shown row of a tree reaches past the view's right edge. Each tab of every tabbed pane is selected in turn (and the first one selected again), so the fields on
 * hidden tabs are looked at too. Call with the window shown at its default size, from any thread.
 *
 * <pre>
 *   List&lt;String&gt; problems = WindowVisibility.problems(frame);   // "writer.batchSize: outside the window ..."
 *   WindowVisibility.assertEverythingVisible(frame);                // throws AssertionError listing them
 * </pre>
 */
public final class WindowVisibility {
    private WindowVisibility() {
    }

    /** Throws an {@link AssertionError} listing every problem {@link #problems} finds. */
    public static void assertEverythingVisible(Window window) {
        List<String> found = problems(window);
        if (!found.isEmpty()) {
            throw new AssertionError(found.size() + " thing(s) a person cannot see in '" + title(window) + "' at "
                    + window.getWidth() + "x" + window.getHeight() + ":\n  " + String.join("\n  ", found));
        }
    }

    /** One line per component that is hidden, clipped, zero-sized or cut; empty when everything can be seen. */
    public static List<String> problems(Window window) {
        try {
            return OnEdt.call(() -> inspect(window));
        } catch (Exception e) {
            throw new IllegalStateException("could not inspect the window: " + e, e);
        }
    }

    private static List<String> inspect(Window window) {
        List<String> out = new ArrayList<>();
        window.validate();
        Rectangle visible = visibleArea(window);
        List<JTabbedPane> tabbed = new ArrayList<>();
        collect(window, JTabbedPane.class, tabbed);
        if (tabbed.isEmpty()) {
            check(window, window, visible, "", out);
            return out;
        }
        // Each tab of each tabbed pane in turn; components outside tabs are checked with the first tab shown.
        for (JTabbedPane pane : tabbed) {
            int selected = pane.getSelectedIndex();
            for (int i = 0; i < pane.getTabCount(); i++) {
                pane.setSelectedIndex(i);
                window.validate();
                check(window, window, visible, "tab '" + pane.getTitleAt(i) + "': ", out);
            }
            pane.setSelectedIndex(selected);
            window.validate();
        }
        return out.stream().distinct().toList();
    }

    private static void check(Window window, Container root, Rectangle visible, String where, List<String> out) {
        for (Component c : root.getComponents()) {
            if (!c.isVisible() || c instanceof JScrollBar || c instanceof BasicSplitPaneDivider) {
                continue; // their arrow buttons are the look and feel's, not the window's
            }
            if (isInput(c)) {
                // a table, list or tree scrolls inside its viewport: the scroll pane is what must be on screen
                Component placed = c.getParent() instanceof JViewport port && port.getParent() instanceof JScrollPane sp
                        && c instanceof Scrollable ? sp : c;
                String problem = placement(window, placed, visible);
                if (problem != null) {
                    out.add(where + describe(c) + ": " + problem);
                }
            }
            String cut = cutText(c);
            if (cut != null && c.isShowing()) {
                out.add(where + describe(c) + ": " + cut);
            }
            if (c instanceof JTable table && c.isShowing()) {
                cutCells(table).forEach(p -> out.add(where + describe(c) + ": " + p));
            }
            if (c instanceof JTree tree && c.isShowing()) {
                cutRows(tree).forEach(p -> out.add(where + describe(c) + ": " + p));
            }
            if (c instanceof Container child && !(c instanceof JComboBox<?>) && !(c instanceof JSpinner)) {
                if (c instanceof JTabbedPane pane) {
                    Component shown = pane.getSelectedComponent();
                    if (shown instanceof Container tab) {
                        check(window, tab, visible, where, out);
                    }
                    continue;
                }
                check(window, child, visible, where, out);
            }
        }
    }

    /** Null when the component is showing, has a size, and lies wholly in the window and in its scroll panes' views. */
    private static String placement(Window window, Component c, Rectangle visible) {
        if (!c.isShowing()) {
            return "not showing";
        }
        if (c.getWidth() <= 0 || c.getHeight() <= 0) {
            return "zero-sized (" + c.getWidth() + "x" + c.getHeight() + ")";
        }
        Rectangle inWindow = SwingUtilities.convertRectangle(c.getParent(), c.getBounds(), window);
        if (!visible.contains(inWindow)) {
            return "outside the window: at " + inWindow.x + "," + inWindow.y + " size " + inWindow.width + "x"
                    + inWindow.height + ", the window shows " + visible.x + "," + visible.y + " to "
                    + (visible.x + visible.width) + "," + (visible.y + visible.height);
        }
        if (c instanceof JComponent jc) {
            Rectangle seen = jc.getVisibleRect();
            if (seen.width < c.getWidth() || seen.height < c.getHeight()) {
                return "clipped: " + seen.width + "x" + seen.height + " of " + c.getWidth() + "x" + c.getHeight()
                        + " can be seen";
            }
        }
        return null;
    }

    /** The part of the window inside its borders and title bar, in window coordinates. */
    private static Rectangle visibleArea(Window window) {
        if (window instanceof javax.swing.RootPaneContainer rpc) {
            JRootPane root = rpc.getRootPane();
            return SwingUtilities.convertRectangle(root.getParent(), root.getBounds(), window);
        }
        java.awt.Insets in = window.getInsets();
        return new Rectangle(in.left, in.top, window.getWidth() - in.left - in.right,
                window.getHeight() - in.top - in.bottom);
    }

    private static boolean isInput(Component c) {
        return c instanceof JTextComponent t && t.isEditable() || c instanceof AbstractButton || c instanceof JComboBox<?>
                || c instanceof JSpinner || c instanceof JSlider || c instanceof JList<?> || c instanceof JTable
                || c instanceof JTree;
    }

    /** Why a label's or button's text is shown cut ("..."), or null when it is shown whole. */
    private static String cutText(Component c) {
        String text = c instanceof JLabel l ? l.getText() : c instanceof AbstractButton b ? b.getText() : null;
        if (text == null || text.isBlank() || text.startsWith("<html>") || c.getWidth() <= 0) {
            return null;
        }
        JComponent jc = (JComponent) c;
        java.awt.Insets in = jc.getInsets();
        int needed = c.getPreferredSize().width;
        if (c.getWidth() < needed) {
            return "text cut: '" + text + "' needs " + needed + " px, has " + c.getWidth() + " (" + in.left + "+"
                    + in.right + " insets)";
        }
        Rectangle seen = jc.getVisibleRect();
        if (seen.width < c.getWidth() && seen.width < needed) {
            return "text cut by its container: '" + text + "' shows " + seen.width + " of " + needed + " px";
        }
        return null;
    }

    /** The header titles and cells of a table drawn narrower than their text. */
    private static List<String> cutCells(JTable table) {
        List<String> out = new ArrayList<>();
        for (int col = 0; col < table.getColumnCount(); col++) {
            int width = table.getColumnModel().getColumn(col).getWidth();
            if (table.getTableHeader() != null) {
                javax.swing.table.TableColumn tc = table.getColumnModel().getColumn(col);
                javax.swing.table.TableCellRenderer hr = tc.getHeaderRenderer() != null ? tc.getHeaderRenderer()
                        : table.getTableHeader().getDefaultRenderer();
                Component h = hr.getTableCellRendererComponent(table, tc.getHeaderValue(), false, false, -1, col);
                if (h.getPreferredSize().width > width) {
                    out.add("column title cut: '" + tc.getHeaderValue() + "' needs " + h.getPreferredSize().width
                            + " px, has " + width);
                }
            }
            for (int row = 0; row < table.getRowCount(); row++) {
                Component r = table.prepareRenderer(table.getCellRenderer(row, col), row, col);
                if (r.getPreferredSize().width > width) {
                    out.add("cell text cut: '" + table.getValueAt(row, col) + "' (row " + row + ") needs "
                            + r.getPreferredSize().width + " px, has " + width);
                }
            }
        }
        return out;
    }

    /** The rows of a tree that reach past the right edge of the view it is scrolled in (or of itself). */
    private static List<String> cutRows(JTree tree) {
        List<String> out = new ArrayList<>();
        Rectangle seen = tree.getVisibleRect();
        for (int row = 0; row < tree.getRowCount(); row++) {
            Rectangle r = tree.getRowBounds(row);
            if (r != null && r.y < seen.y + seen.height && r.y + r.height > seen.y && r.x + r.width > seen.x + seen.width) {
                out.add("row cut: '" + tree.getPathForRow(row).getLastPathComponent() + "' reaches " + (r.x + r.width)
                        + " px, the view shows " + (seen.x + seen.width));
            }
        }
        return out;
    }

    private static <T> void collect(Container root, Class<T> type, List<T> into) {
        for (Component c : root.getComponents()) {
            if (type.isInstance(c) && c.isVisible()) {
                into.add(type.cast(c));
            }
            if (c instanceof Container child) {
                collect(child, type, into);
            }
        }
    }

    private static String describe(Component c) {
        String text = c instanceof JLabel l ? l.getText() : c instanceof AbstractButton b ? b.getText() : null;
        String name = c.getName() != null ? "'" + c.getName() + "'" : text != null && !text.isBlank() ? "'" + text + "'" : "";
        return c.getClass().getSimpleName() + (name.isEmpty() ? "" : " " + name);
    }

    private static String title(Window w) {
        return w instanceof java.awt.Frame f ? f.getTitle() : w instanceof java.awt.Dialog d ? d.getTitle() : w.getName();
    }
}
