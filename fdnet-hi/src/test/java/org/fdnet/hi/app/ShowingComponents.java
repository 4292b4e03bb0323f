package org.fdnet.hi.app;

import java.awt.Component;
import java.awt.Container;
import javax.swing.AbstractButton;

/** How GUI scenarios find a window's parts: by type and by name (or, for buttons, their text). Call on the Swing thread. */
final class ShowingComponents {
    private ShowingComponents() {
    }

    /** The showing component of that type whose name (or, for buttons, text) is {@code key}; any, for {@code null}. */
    static <T extends Component> T find(Container root, Class<T> type, String key) {
        for (Component c : root.getComponents()) {
            if (type.isInstance(c) && c.isShowing() && (key == null || key.equals(c.getName())
                    || c instanceof AbstractButton b && key.equals(b.getText()))) {
                return type.cast(c);
            }
            if (c instanceof Container inner) {
                T found = find(inner, type, key);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }
}
