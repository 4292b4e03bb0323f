package org.fdnet.event.wire;

import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * A node the logger knows: its global source id (the {@code sourceid} of the logger's tables), the run it
 * belongs to, its kind and its name. On the wire: {@code i32 sourceId, i32 runId, u8 kind, string module,
 * string node}.
 */
public record LoggedNode(int sourceId, int runId, NodeKind kind, NodeRef name) {

    public void write(FrameWriter w) {
        w.putInt(sourceId).putInt(runId).putByte(kind == NodeKind.DATA ? 1 : 2)
                .putString(name.module()).putString(name.node());
    }

    public static LoggedNode read(Frame f) throws ProtocolException {
        int source = f.getInt();
        int run = f.getInt();
        int kind = f.getByte();
        return new LoggedNode(source, run, kind == 1 ? NodeKind.DATA : NodeKind.RELATION,
                new NodeRef(f.getString(), f.getString()));
    }
}
