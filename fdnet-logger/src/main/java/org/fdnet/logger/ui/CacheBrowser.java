package org.fdnet.logger.ui;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.util.List;
import java.util.function.Supplier;
import javax.swing.DefaultComboBoxModel;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.cache.CacheEntry;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.netinfo.NodeKind;

/**
 * The panel's cache browser (thesis, chapter 4, the Logger panel): pick a Data the logger knows, see every
 * event of it the cache holds now — written to the database or not, monitored by a viewer or not. A snapshot
 * taken when a Data is picked or <em>Refresh</em> is pressed; the cache moves on meanwhile.
 *
 * <p>Component names (for tests): {@code cacheNode}, {@code cacheRefresh}, {@code cacheEvents},
 * {@code cacheSummary}.
 */
final class CacheBrowser extends JPanel {
    private final Supplier<NetworkStateLogger> logger;
    private final DefaultComboBoxModel<NodeChoice> nodes = new DefaultComboBoxModel<>();
    private final JComboBox<NodeChoice> picker = new JComboBox<>(nodes);
    private final CacheEntryTableModel events = new CacheEntryTableModel();
    private final JLabel summary = new JLabel("start the logger, then pick a Data");
    private boolean refilling;

    /** One Data in the picker, shown as Module/Node (run N). */
    record NodeChoice(LoggedNode node) {
        @Override
        public String toString() {
            return node.name() + " (run " + node.runId() + ")";
        }
    }

    CacheBrowser(Supplier<NetworkStateLogger> logger) {
        super(new BorderLayout(4, 4));
        this.logger = logger;
        picker.setName("cacheNode");
        JButton refresh = new JButton("Refresh");
        refresh.setName("cacheRefresh");
        JTable table = new JTable(events);
        table.setName("cacheEvents");
        summary.setName("cacheSummary");
        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT));
        top.add(new JLabel("Data:"));
        top.add(picker);
        top.add(refresh);
        add(top, BorderLayout.NORTH);
        add(new JScrollPane(table), BorderLayout.CENTER);
        add(summary, BorderLayout.SOUTH);
        picker.addActionListener(e -> {
            if (!refilling) {
                showPicked();
            }
        });
        refresh.addActionListener(e -> refresh());
    }

    /** Reloads the Datas the logger knows (keeping the pick when it is still there) and the picked one's events. */
    void refresh() {
        NetworkStateLogger l = logger.get();
        if (l == null || !l.running()) {
            nodes.removeAllElements();
            events.update(List.of());
            summary.setText("the logger is not running");
            return;
        }
        Object picked = nodes.getSelectedItem();
        refilling = true;
        try {
            nodes.removeAllElements();
            for (LoggedNode n : l.directory().nodes("")) {
                if (n.kind() == NodeKind.DATA) {
                    nodes.addElement(new NodeChoice(n));
                }
            }
            if (picked != null && nodes.getIndexOf(picked) >= 0) {
                nodes.setSelectedItem(picked);
            }
        } finally {
            refilling = false;
        }
        showPicked();
    }

    private void showPicked() {
        NetworkStateLogger l = logger.get();
        NodeChoice choice = (NodeChoice) nodes.getSelectedItem();
        if (l == null || !l.running() || choice == null) {
            events.update(List.of());
            summary.setText(nodes.getSize() == 0 ? "no Data logged yet" : "pick a Data");
            return;
        }
        List<CacheEntry> held = l.cache().entriesOf(choice.node().sourceId());
        events.update(held);
        long monitored = held.stream().filter(CacheEntry::monitored).count();
        long written = held.stream().filter(CacheEntry::written).count();
        summary.setText(String.format("%s: %,d events in the cache, %,d written, %,d not yet written, %,d monitored",
                choice.node().name(), held.size(), written, held.size() - written, monitored));
    }
}
