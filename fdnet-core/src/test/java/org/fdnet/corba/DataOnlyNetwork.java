package org.fdnet.corba;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * A {@link LocalNetwork} of Data cells only (values and their observers, no Relations): the seam fake for
 * the transport's tests, where a host in the test JVM only publishes or observes values. Real hosts run
 * {@link RuntimeLocalNetwork}.
 */
final class DataOnlyNetwork implements LocalNetwork {
    private final Map<NodeRef, Cell> cells = new ConcurrentHashMap<>();

    private static final class Cell {
        final List<ValueObserver> observers = new CopyOnWriteArrayList<>();
        Object value;

        synchronized void set(Object v, String fromHost, ValueOrigin origin) {
            value = v;
            for (ValueObserver o : observers) {
                o.onValue(v, fromHost, origin);
            }
        }

        synchronized Object get() {
            return value;
        }
    }

    @Override
    public void create(NodeRef ref, NodeInfo node) {
        if (node.kind() == NodeKind.RELATION) {
            throw new UnsupportedOperationException("Relation " + ref + " needs the runtime engine; this host holds Datas only");
        }
        add(ref);
    }

    @Override
    public void createStandIn(NodeRef ref, NodeInfo node) {
        add(ref);
    }

    private void add(NodeRef ref) {
        if (cells.putIfAbsent(ref, new Cell()) != null) {
            throw new IllegalStateException(ref + " already exists on this host");
        }
    }

    @Override
    public void destroy(NodeRef ref) {
        if (cells.remove(ref) == null) {
            throw new NoSuchElementException(ref.toString());
        }
    }

    @Override
    public List<NodeRef> nodes() {
        return new ArrayList<>(cells.keySet());
    }

    @Override
    public boolean knows(NodeRef ref) {
        return cells.containsKey(ref);
    }

    @Override
    public void connect(ConnectionInfo connection) {
        throw new UnsupportedOperationException(connection + " needs a Relation; this host holds Datas only");
    }

    @Override
    public void disconnect(ConnectionInfo connection) {
        throw new UnsupportedOperationException(connection + " needs a Relation; this host holds Datas only");
    }

    @Override
    public Object read(NodeRef data) {
        return cell(data).get();
    }

    @Override
    public void write(NodeRef data, Object value) {
        cell(data).set(value, null, null);
    }

    @Override
    public void inject(NodeRef data, Object value, String originHost, ValueOrigin origin) {
        cell(data).set(value, originHost, origin);
    }

    @Override
    public AutoCloseable observe(NodeRef data, ValueObserver observer) {
        Cell c = cell(data);
        c.observers.add(observer);
        return () -> c.observers.remove(observer);
    }

    private Cell cell(NodeRef ref) {
        Cell c = cells.get(ref);
        if (c == null) {
            throw new NoSuchElementException("no Data " + ref + " on this host");
        }
        return c;
    }
}
