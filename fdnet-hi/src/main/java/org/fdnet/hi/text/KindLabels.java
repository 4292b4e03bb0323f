package org.fdnet.hi.text;

import java.awt.Component;
import java.util.function.Function;

import javax.swing.DefaultListCellRenderer;
import javax.swing.JList;

/** Shows a kind in a list by the word users see ("Data", "Reader"), not its constant name. */
final class KindLabels<T> extends DefaultListCellRenderer {
    private final transient Function<T, String> label;

    KindLabels(Function<T, String> label) {
        this.label = label;
    }

    @Override
    @SuppressWarnings("unchecked")
    public Component getListCellRendererComponent(JList<?> list, Object value, int index, boolean selected,
                                                  boolean focused) {
        Object shown = value == null ? "" : label.apply((T) value);
        return super.getListCellRendererComponent(list, shown, index, selected, focused);
    }
}
