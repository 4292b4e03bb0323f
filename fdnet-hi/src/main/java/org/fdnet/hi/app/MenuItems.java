package org.fdnet.hi.app;

import java.awt.event.ActionEvent;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.KeyStroke;

/** A menu action from a name, an optional accelerator ("control Z") and what it does. */
final class MenuItems {
    private MenuItems() {
    }

    static Action action(String name, String accelerator, Runnable run) {
        Action a = new AbstractAction(name) {
            @Override
            public void actionPerformed(ActionEvent e) {
                run.run();
            }
        };
        if (accelerator != null) {
            a.putValue(Action.ACCELERATOR_KEY, KeyStroke.getKeyStroke(accelerator));
        }
        return a;
    }
}
