package org.fdnet.netinfo.xml;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.netinfo.xml.binding.CnetElement;
import org.fdnet.netinfo.xml.binding.ConnectionElement;
import org.fdnet.netinfo.xml.binding.DStructureElement;
import org.fdnet.netinfo.xml.binding.LinkElement;
import org.fdnet.netinfo.xml.binding.Located;
import org.fdnet.netinfo.xml.binding.LocatedText;
import org.fdnet.netinfo.xml.binding.ModuleBody;
import org.fdnet.netinfo.xml.binding.ModuleElement;
import org.fdnet.netinfo.xml.binding.ParamElement;
import org.fdnet.netinfo.xml.binding.ReadElement;
import org.fdnet.netinfo.xml.binding.StructureElement;
import org.fdnet.netinfo.xml.binding.WriteElement;

/**
 * Turns a .fdn file into a {@link NetworkInfo}: first the DTD (by {@link GuardedXmlReader}), then the
 * rules a DTD cannot say, each reported at its line: unique module names (a nested module is named by its path,
 * {@code Arm/Hand}), unique node names per
 * module, typed parameter values, and connections whose names resolve (own module, then main) to one
 * Data and one Relation. The model's own edit rules do the checking, so a file and an edit can never
 * disagree on what is valid.
 */
final class NetworkFileReader {
    private final Path file;
    private final GuardedXmlReader xml;

    NetworkFileReader(Path file) {
        this.file = file;
        this.xml = new GuardedXmlReader(file, BundledDtd.CNET);
    }

    /** Reads a document held in memory; problems name {@code source}. */
    NetworkFileReader(Path source, byte[] content) {
        this.file = source;
        this.xml = new GuardedXmlReader(source, content, BundledDtd.CNET);
    }

    NetworkDocument read() throws NetworkFileException {
        CnetElement root = xml.read(JaxbContexts.network(), CnetElement.class);
        if (root == null || !xml.problems().isEmpty()) {
            throw new NetworkFileException(xml.problems());
        }
        NetworkInfo network = new NetworkInfo(root.name == null ? null : root.name.strip());
        Map<String, ModuleBody> bodies = declareModules(network, root);
        bodies.forEach((module, body) -> declareNodes(network, module, body));
        bodies.forEach((module, body) -> declareConnections(network, module, body));
        if (!xml.problems().isEmpty()) {
            throw new NetworkFileException(xml.problems());
        }
        return new NetworkDocument(file, network, xml.doctypeSystemId(), xml.leadingComments(), xml.innerComments());
    }

    private Map<String, ModuleBody> declareModules(NetworkInfo network, CnetElement root) {
        Map<String, ModuleBody> bodies = new LinkedHashMap<>();
        bodies.put(ModuleInfo.MAIN, root);
        declareModules(network, null, root.modules, bodies);
        return bodies;
    }

    /** Declares {@code elements} inside module {@code parent} ({@code null}: the top level), then what each holds. */
    private void declareModules(NetworkInfo network, String parent, List<ModuleElement> elements, Map<String, ModuleBody> bodies) {
        for (ModuleElement m : elements) {
            String name = m.name.strip();
            if (ModuleInfo.MAIN.equals(name)) {
                problem(m, "module name 'main' is reserved: the top-level nodes and connections form module main");
                continue;
            }
            if (name.indexOf('/') >= 0) {
                problem(m, "module name '" + name + "' may not contain '/': nest a module element inside another instead");
                continue;
            }
            String path = parent == null ? name : parent + "/" + name;
            try {
                network.addModule(path, "yes".equals(m.loadatstart));
                bodies.put(path, m);
                declareModules(network, path, m.modules, bodies);
            } catch (EditRefusedException e) {
                problem(m, e.getMessage());
            }
        }
    }

    private void declareNodes(NetworkInfo network, String module, ModuleBody body) {
        for (StructureElement s : body.structures) {
            declareNode(network, module, s);
        }
        for (ConnectionElement group : body.connections) {
            for (LinkElement link : group.links) {
                if (link instanceof ReadElement read) {
                    if (read.dstructure != null) {
                        declareNode(network, module, read.dstructure);
                    }
                    if (read.pstructure != null) {
                        declareNode(network, module, read.pstructure);
                    }
                }
            }
        }
    }

    private void declareNode(NetworkInfo network, String module, StructureElement s) {
        NodeKind kind = s instanceof DStructureElement ? NodeKind.DATA : NodeKind.RELATION;
        String name = s.name.strip();
        List<Parameter> parameters = new ArrayList<>();
        for (ParamElement p : s.params) {
            try {
                parameters.add(new Parameter(p.name == null ? null : p.name.strip(),
                        ParameterType.fromAttribute(p.type), p.value));
            } catch (IllegalArgumentException e) {
                String which = p.name == null ? "a parameter" : "parameter '" + p.name.strip() + "'";
                problem(p, "node '" + name + "': " + which + " of type " + p.type + ": " + e.getMessage());
            }
        }
        NodeInfo node = new NodeInfo(kind, name, s.host.strip(), s.path.strip(), s.className.strip(), parameters);
        try {
            network.addNode(module, node);
        } catch (EditRefusedException e) {
            problem(s, e.getMessage());
        }
    }

    private void declareConnections(NetworkInfo network, String module, ModuleBody body) {
        for (ConnectionElement group : body.connections) {
            for (LinkElement link : group.links) {
                ConnectionInfo connection = link instanceof ReadElement read
                        ? reader(network, module, read)
                        : writer(network, module, (WriteElement) link);
                if (connection == null) {
                    continue;
                }
                try {
                    network.addConnection(module, connection);
                } catch (EditRefusedException e) {
                    problem(link, "in module '" + module + "': " + e.getMessage());
                }
            }
        }
    }

    private ConnectionInfo reader(NetworkInfo network, String module, ReadElement read) {
        NodeRef data = read.dstructure != null
                ? new NodeRef(module, read.dstructure.name.strip())
                : resolve(network, module, read, read.data, ConnectionKind.READER);
        NodeRef relation = read.pstructure != null
                ? new NodeRef(module, read.pstructure.name.strip())
                : resolve(network, module, read, read.proc, ConnectionKind.READER);
        if (data == null || relation == null) {
            return null;
        }
        return new ConnectionInfo(ConnectionKind.READER, linkName(read), data, relation, exists(read),
                read.dstructure != null, read.pstructure != null);
    }

    private ConnectionInfo writer(NetworkInfo network, String module, WriteElement write) {
        NodeRef data = resolve(network, module, write, write.data, ConnectionKind.WRITER);
        NodeRef relation = resolve(network, module, write, write.proc, ConnectionKind.WRITER);
        if (data == null || relation == null) {
            return null;
        }
        return new ConnectionInfo(ConnectionKind.WRITER, linkName(write), data, relation, exists(write), false, false);
    }

    /** JAXB gives no position to a text-only element, so a bad reference is reported at its {@code read}/{@code write}. */
    private NodeRef resolve(NetworkInfo network, String module, LinkElement link, LocatedText reference, ConnectionKind kind) {
        String text = reference.text.strip();
        NodeRef ref = network.resolve(module, text);
        if (ref == null) {
            String where;
            if (text.indexOf('/') >= 0) {
                where = describeQualified(network, NodeRef.parse(text, module));
            } else if (ModuleInfo.MAIN.equals(module)) {
                where = "module 'main' has no node named '" + text + "'";
            } else if (module.indexOf('/') >= 0) {
                where = "neither module '" + module + "', the modules enclosing it, nor module 'main' has a node named '" + text + "'";
            } else {
                where = "neither module '" + module + "' nor module 'main' has a node named '" + text + "'";
            }
            problem(link, "in module '" + module + "': " + kind.label() + " names '" + text + "', but " + where);
        }
        return ref;
    }

    private static String describeQualified(NetworkInfo network, NodeRef ref) {
        return network.module(ref.module()) == null
                ? "there is no module '" + ref.module() + "'"
                : "module '" + ref.module() + "' has no node named '" + ref.node() + "'";
    }

    private static String linkName(LinkElement link) {
        return link.linkName() == null ? null : link.linkName().strip();
    }

    private static boolean exists(LinkElement link) {
        return link.exist() == null || !"no".equals(link.exist().value);
    }

    private void problem(Located where, String message) {
        xml.add(where.line(), where.column(), message);
    }
}
