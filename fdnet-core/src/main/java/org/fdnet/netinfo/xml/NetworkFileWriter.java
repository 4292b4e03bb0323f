package org.fdnet.netinfo.xml;

import jakarta.xml.bind.JAXBException;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.xml.binding.CnetElement;
import org.fdnet.netinfo.xml.binding.ConnectionElement;
import org.fdnet.netinfo.xml.binding.DStructureElement;
import org.fdnet.netinfo.xml.binding.ExistElement;
import org.fdnet.netinfo.xml.binding.LocatedText;
import org.fdnet.netinfo.xml.binding.ModuleBody;
import org.fdnet.netinfo.xml.binding.ModuleElement;
import org.fdnet.netinfo.xml.binding.PStructureElement;
import org.fdnet.netinfo.xml.binding.ParamElement;
import org.fdnet.netinfo.xml.binding.ReadElement;
import org.fdnet.netinfo.xml.binding.StructureElement;
import org.fdnet.netinfo.xml.binding.WriteElement;

/**
 * Writes a {@link NetworkInfo} as a .fdn file in canonical form: UTF-8, a DOCTYPE, four-space
 * indentation, modules (a nested module inside its parent's element), nodes and connections in model order (which is file order for a loaded
 * network), each module's connections in one {@code connection} element, references in their
 * shortest unambiguous form. Nodes a file declared inside a {@code read} are written back there,
 * as long as that keeps the node order; otherwise they become ordinary structures.
 */
final class NetworkFileWriter {
    private final NetworkInfo network;

    NetworkFileWriter(NetworkInfo network) {
        this.network = network;
    }

    void write(OutputStream out, String doctypeSystemId, List<String> leadingComments) throws IOException {
        StringBuilder header = new StringBuilder("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!DOCTYPE cnet SYSTEM \"")
                .append(doctypeSystemId.replace("\"", "%22")).append("\">\n");
        for (String comment : leadingComments) {
            header.append("<!--").append(comment.replace("--", "- -")).append("-->\n");
        }
        out.write(header.toString().getBytes(StandardCharsets.UTF_8));
        try {
            XmlFragments.marshal(JaxbContexts.network(), toElement(), out);
        } catch (JAXBException e) {
            throw new IOException("cannot write network '" + network.name() + "': " + e.getMessage(), e);
        }
    }

    private CnetElement toElement() {
        CnetElement root = new CnetElement();
        root.name = network.name();
        Map<String, ModuleElement> elements = new HashMap<>();
        for (ModuleInfo module : network.modules()) {
            if (module.isMain()) {
                fill(root, module);
            } else {
                ModuleElement element = new ModuleElement();
                element.name = module.localName();
                element.loadatstart = module.loadAtStart() ? "yes" : "no";
                fill(element, module);
                String parent = module.parentName();
                (parent == null ? root.modules : elements.get(parent).modules).add(element);
                elements.put(module.name(), element);
            }
        }
        return root;
    }

    private void fill(ModuleBody body, ModuleInfo module) {
        Set<String> inline = inlineNodes(module);
        for (NodeInfo node : module.nodes()) {
            if (!inline.contains(node.name())) {
                body.structures.add(structure(node));
            }
        }
        if (module.connections().isEmpty()) {
            return;
        }
        ConnectionElement group = new ConnectionElement();
        Set<String> written = new LinkedHashSet<>();
        for (ConnectionInfo c : module.connections()) {
            group.links.add(c.kind() == ConnectionKind.READER
                    ? read(module, c, inline, written)
                    : write(module, c));
        }
        body.connections.add(group);
    }

    private ReadElement read(ModuleInfo module, ConnectionInfo c, Set<String> inline, Set<String> written) {
        ReadElement read = new ReadElement();
        read.name = c.name();
        if (claims(module, c.data(), c.dataInline(), inline, written)) {
            read.dstructure = (DStructureElement) structure(network.node(c.data()));
        } else {
            read.data = new LocatedText(network.referenceText(module.name(), c.data()));
        }
        if (claims(module, c.relation(), c.relationInline(), inline, written)) {
            read.pstructure = (PStructureElement) structure(network.node(c.relation()));
        } else {
            read.proc = new LocatedText(network.referenceText(module.name(), c.relation()));
        }
        read.exist = exist(c);
        return read;
    }

    private static boolean claims(ModuleInfo module, NodeRef end, boolean flagged, Set<String> inline, Set<String> written) {
        return flagged && end.module().equals(module.name()) && inline.contains(end.node()) && written.add(end.node());
    }

    private WriteElement write(ModuleInfo module, ConnectionInfo c) {
        WriteElement write = new WriteElement();
        write.name = c.name();
        write.data = new LocatedText(network.referenceText(module.name(), c.data()));
        write.proc = new LocatedText(network.referenceText(module.name(), c.relation()));
        write.exist = exist(c);
        return write;
    }

    private static ExistElement exist(ConnectionInfo c) {
        if (c.exists()) {
            return null;
        }
        ExistElement exist = new ExistElement();
        exist.value = "no";
        return exist;
    }

    /**
     * The nodes to write inside their {@code read}: those flagged inline, claimed by the first Reader
     * that flags them, provided that reading the file back yields the same node order (structures
     * first, then inline nodes in connection order). Otherwise none.
     */
    private static Set<String> inlineNodes(ModuleInfo module) {
        Set<String> claimed = new LinkedHashSet<>();
        for (ConnectionInfo c : module.connections()) {
            if (c.kind() != ConnectionKind.READER) {
                continue;
            }
            if (c.dataInline() && c.data().module().equals(module.name()) && module.hasNode(c.data().node())) {
                claimed.add(c.data().node());
            }
            if (c.relationInline() && c.relation().module().equals(module.name()) && module.hasNode(c.relation().node())) {
                claimed.add(c.relation().node());
            }
        }
        if (claimed.isEmpty()) {
            return claimed;
        }
        List<String> modelOrder = new ArrayList<>();
        List<String> fileOrder = new ArrayList<>();
        for (NodeInfo node : module.nodes()) {
            modelOrder.add(node.name());
            if (!claimed.contains(node.name())) {
                fileOrder.add(node.name());
            }
        }
        fileOrder.addAll(claimed);
        return fileOrder.equals(modelOrder) ? claimed : Set.of();
    }

    private static StructureElement structure(NodeInfo node) {
        StructureElement s = node.kind() == NodeKind.DATA ? new DStructureElement() : new PStructureElement();
        s.name = node.name();
        s.host = node.host();
        s.path = node.path();
        s.className = node.className();
        for (Parameter p : node.parameters()) {
            ParamElement element = new ParamElement();
            element.name = p.name();
            element.type = p.type() == null ? null : p.type().attribute();
            element.value = p.value();
            s.params.add(element);
        }
        return s;
    }
}
