package org.fdnet.hi.app;

import java.awt.Component;
import java.awt.Container;
import java.util.function.BooleanSupplier;
import javax.swing.AbstractButton;
import org.fdnet.hi.live.LiveTestNetwork;

/** How GUI scenarios find an editor window's parts (by type and name, or a button's text) and wait for its state. */
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

    /** Waits (at most 20 s), checking on the Swing thread, until {@code condition} holds; fails naming {@code what}. */
    static void waitFor(HiWindow window, String what, BooleanSupplier condition) throws Exception {
        long deadline = System.nanoTime() + 20_000_000_000L;
        while (System.nanoTime() < deadline) {
            if (LiveTestNetwork.edt(condition::getAsBoolean)) {
                return;
            }
            Thread.sleep(50);
        }
        throw new AssertionError("timed out waiting for: " + what + " (status: "
                + LiveTestNetwork.edt(() -> window.status().message()) + ")");
    }

    static void check(boolean holds, String what) {
        if (!holds) {
            throw new AssertionError("does not hold: " + what);
        }
    }
}
