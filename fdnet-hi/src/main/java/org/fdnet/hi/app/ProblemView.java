package org.fdnet.hi.app;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Font;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.swing.DefaultListModel;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTextArea;
import javax.swing.text.BadLocationException;
import javax.swing.text.DefaultHighlighter;
import org.fdnet.netinfo.xml.Problem;

/**
 * A file that has problems, shown read-only: its text above, the problems ({@code file:line:col: message})
 * below; selecting a problem puts the caret at its place in the text and marks the line.
 */
public final class ProblemView extends JPanel {
    private final JTextArea text = new JTextArea();
    private final JList<Problem> list;

    public ProblemView(Path file, List<Problem> problems) {
        super(new BorderLayout());
        text.setEditable(false);
        text.setName("problems.text");
        text.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 13));
        try {
            text.setText(Files.readString(file, StandardCharsets.UTF_8));
        } catch (IOException e) {
            text.setText("(cannot read " + file + ": " + e.getMessage() + ")");
        }
        DefaultListModel<Problem> model = new DefaultListModel<>();
        problems.forEach(model::addElement);
        list = new JList<>(model);
        list.setName("problems.list");
        list.addListSelectionListener(e -> {
            if (!e.getValueIsAdjusting() && list.getSelectedValue() != null) {
                jumpTo(list.getSelectedValue());
            }
        });
        JLabel heading = new JLabel(problems.size() + (problems.size() == 1 ? " problem" : " problems")
                + " in " + file.getFileName() + " — opened read-only; fix the file and open it again");
        heading.setForeground(new Color(0xC0392B));
        JPanel bottom = new JPanel(new BorderLayout());
        bottom.add(heading, BorderLayout.NORTH);
        bottom.add(new JScrollPane(list), BorderLayout.CENTER);
        JSplitPane split = new JSplitPane(JSplitPane.VERTICAL_SPLIT, new JScrollPane(text), bottom);
        split.setResizeWeight(0.7);
        add(split, BorderLayout.CENTER);
        if (!problems.isEmpty()) {
            list.setSelectedIndex(0);
        }
    }

    /** Caret to the problem's line and column, the line marked. */
    void jumpTo(Problem p) {
        if (p.line() <= 0) {
            return;
        }
        try {
            int line = Math.min(p.line(), text.getLineCount()) - 1;
            int start = text.getLineStartOffset(line);
            int end = text.getLineEndOffset(line);
            text.getHighlighter().removeAllHighlights();
            text.getHighlighter().addHighlight(start, end, new DefaultHighlighter.DefaultHighlightPainter(new Color(0xFFE0E0)));
            text.setCaretPosition(Math.min(end, start + Math.max(p.column(), 1) - 1));
            text.requestFocusInWindow();
            java.awt.geom.Rectangle2D view = text.modelToView2D(start);
            if (view != null) {
                java.awt.Rectangle r = view.getBounds();
                r.height = Math.max(r.height, 1) * 8;
                r.y = Math.max(0, r.y - r.height / 2);
                text.scrollRectToVisible(r);
            }
        } catch (BadLocationException e) {
            throw new IllegalStateException("line " + p.line() + " is in the text", e);
        }
    }

    public int caretLine() {
        try {
            return text.getLineOfOffset(text.getCaretPosition()) + 1;
        } catch (BadLocationException e) {
            throw new IllegalStateException(e);
        }
    }

    public JList<Problem> problemList() {
        return list;
    }
}
