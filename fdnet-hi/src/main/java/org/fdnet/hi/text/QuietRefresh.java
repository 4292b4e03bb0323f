package org.fdnet.hi.text;

import java.util.function.Consumer;

import javax.swing.JComboBox;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import javax.swing.text.JTextComponent;

/**
 * Tells a frame's widgets the user touched from those the frame itself is refreshing: while a SpeedyDesign
 * update sets a widget, its listeners stay silent, so a refresh is never mistaken for typing.
 */
final class QuietRefresh {
    private boolean refreshing;

    /** Runs a widget refresh with the widgets' listeners silenced. */
    void run(Runnable refresh) {
        boolean outer = refreshing;
        refreshing = true;
        try {
            refresh.run();
        } finally {
            refreshing = outer;
        }
    }

    /** Calls {@code typed} with the whole text after each keystroke the user makes in {@code field}. */
    void onType(JTextComponent field, Consumer<String> typed) {
        field.getDocument().addDocumentListener(new DocumentListener() {
            @Override
            public void insertUpdate(DocumentEvent e) {
                fire();
            }

            @Override
            public void removeUpdate(DocumentEvent e) {
                fire();
            }

            @Override
            public void changedUpdate(DocumentEvent e) {
                fire();
            }

            private void fire() {
                if (!refreshing) {
                    typed.accept(field.getText());
                }
            }
        });
    }

    /** Calls {@code chosen} with the item the user chooses in {@code combo}. */
    <T> void onChoose(JComboBox<T> combo, Consumer<T> chosen) {
        combo.addActionListener(e -> {
            if (!refreshing) {
                chosen.accept(combo.getItemAt(combo.getSelectedIndex()));
            }
        });
    }

    /** Sets the text only when it differs, so the caret of an unchanged field stays where it is. */
    static void setText(JTextComponent field, String text) {
        if (!field.getText().equals(text)) {
            field.setText(text);
        }
    }

    /** Replaces a combo's items, keeping the selection when it is still offered. */
    static <T> void setItems(JComboBox<T> combo, java.util.List<T> items, T selected) {
        combo.removeAllItems();
        for (T item : items) {
            combo.addItem(item);
        }
        combo.setSelectedItem(selected != null && items.contains(selected) ? selected : null);
        if (selected == null || !items.contains(selected)) {
            combo.setSelectedIndex(-1);
        }
    }
}
