package org.fdnet.logger.ui;

import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.logger.cache.CacheEntry;

/** The cached events of one node: time (µs), value, written to the database, monitored by a viewer. */
final class CacheEntryTableModel extends ListTableModel<CacheEntry> {
    CacheEntryTableModel() {
        super("Time (µs)", "Value", "Written", "Monitored");
    }

    @Override
    public Class<?> getColumnClass(int column) {
        return column >= 2 ? Boolean.class : column == 0 ? Long.class : String.class;
    }

    @Override
    Object value(CacheEntry e, int column) {
        return switch (column) {
            case 0 -> e.event().time();
            case 1 -> shown(e);
            case 2 -> e.written();
            default -> e.monitored();
        };
    }

    private static String shown(CacheEntry e) {
        if (e.event() instanceof DataValueEvent d) {
            return d.value().text();
        }
        if (e.event() instanceof RelationValueEvent r) {
            return r.value();
        }
        if (e.event() instanceof NetworkCommandEvent c) {
            return c.command().toString();
        }
        return e.event().toString();
    }
}
