package org.fdnet.event.wire;

import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * A node the logger knows: its global source id (the {@code sourceid} of the logger's tables), the run it
 * belongs to, its kind and its name. On the wire: {@code i32 sourceId, i32 runId, u8 kind, string module,
 * string node}.
 *
 * @param sourceId the node's id in the logger's tables
 * @param runId    the logger's id of the stream it belongs to
 * @param kind     Data or Relation
 * @param name     the node's module and name
 */
public record LoggedNode(int sourceId, int runId, NodeKind kind, NodeRef name) {

    /**
     * Appends this node to the frame {@code w} is building.
     *
     * @param w a writer inside a frame
     */
    public void write(FrameWriter w) {
        w.putInt(sourceId).putInt(runId).putByte(kind == NodeKind.DATA ? 1 : 2)
                .putString(name.module()).putString(name.node());
    }

    /**
     * Reads one node at the frame's cursor.
     *
     * @param f a frame positioned on a node
     * @return the node; the cursor is after it
     * @throws ProtocolException when the payload ends inside it
     */
    public static LoggedNode read(Frame f) throws ProtocolException {
        int source = f.getInt();
        int run = f.getInt();
        int kind = f.getByte();
        return new LoggedNode(source, run, kind == 1 ? NodeKind.DATA : NodeKind.RELATION,
                new NodeRef(f.getString(), f.getString()));
    }
}
