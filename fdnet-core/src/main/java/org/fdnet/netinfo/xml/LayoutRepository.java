package org.fdnet.netinfo.xml;

import jakarta.xml.bind.JAXBException;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import org.fdnet.layout.ModuleLayout;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.layout.NodeLayout;
import org.fdnet.netinfo.xml.binding.FdgElement;
import org.fdnet.netinfo.xml.binding.FdgModuleElement;
import org.fdnet.netinfo.xml.binding.FdgNodeElement;

/**
 * Loads and saves .fdg graphic side files with the same guarded, validating reader as .fdn files,
 * checking what the DTD cannot: numbers, positive sizes, {@code #RRGGBB} colours, unique names.
 */
public final class LayoutRepository {
    private LayoutRepository() {
    }

    /** {@code robot.fdn} → {@code robot.fdg}, beside it. */
    public static Path sideFileOf(Path networkFile) {
        String name = networkFile.getFileName().toString();
        String base = name.toLowerCase(Locale.ROOT).endsWith(".fdn") ? name.substring(0, name.length() - 4) : name;
        return networkFile.resolveSibling(base + ".fdg");
    }

    public static NetworkLayout load(Path file) throws NetworkFileException {
        return read(new GuardedXmlReader(file, BundledDtd.FDG));
    }

    /** Reads a side file held in memory; problems name {@code source}. */
    static NetworkLayout read(Path source, byte[] content) throws NetworkFileException {
        return read(new GuardedXmlReader(source, content, BundledDtd.FDG));
    }

    private static NetworkLayout read(GuardedXmlReader xml) throws NetworkFileException {
        FdgElement root = xml.read(JaxbContexts.layout(), FdgElement.class);
        if (root == null || !xml.problems().isEmpty()) {
            throw new NetworkFileException(xml.problems());
        }
        NetworkLayout layout = new NetworkLayout();
        layout.setNetwork(root.network);
        for (FdgModuleElement m : root.modules) {
            if (layout.module(m.name) != null) {
                xml.add(m.line(), m.column(), "module '" + m.name + "' appears twice");
                continue;
            }
            ModuleLayout module = layout.moduleOrNew(m.name);
            module.setVisible(!"no".equals(m.visible));
            try {
                module.setColour(m.colour);
            } catch (IllegalArgumentException e) {
                xml.add(m.line(), m.column(), "module '" + m.name + "': " + e.getMessage());
            }
            for (FdgNodeElement n : m.nodes) {
                readNode(xml, module, n);
            }
        }
        if (!xml.problems().isEmpty()) {
            throw new NetworkFileException(xml.problems());
        }
        return layout;
    }

    private static void readNode(GuardedXmlReader xml, ModuleLayout module, FdgNodeElement n) {
        String where = "node '" + module.name() + "/" + n.name + "': ";
        if (module.node(n.name) != null) {
            xml.add(n.line(), n.column(), where + "appears twice");
            return;
        }
        try {
            module.put(n.name, new NodeLayout(number("x", n.x), number("y", n.y),
                    n.width == null ? null : number("width", n.width),
                    n.height == null ? null : number("height", n.height), n.colour));
        } catch (IllegalArgumentException e) {
            xml.add(n.line(), n.column(), where + e.getMessage());
        }
    }

    private static double number(String attribute, String text) {
        try {
            return Double.parseDouble(text.strip());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(attribute + " '" + text + "' is not a number", e);
        }
    }

    public static void save(NetworkLayout layout, Path file) throws IOException {
        AtomicFile.write(file, out -> write(layout, out));
    }

    public static void write(NetworkLayout layout, OutputStream out) throws IOException {
        out.write(("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!DOCTYPE fdg SYSTEM \""
                + BundledDtd.FDG.fileName() + "\">\n").getBytes(StandardCharsets.UTF_8));
        FdgElement root = new FdgElement();
        root.network = layout.network();
        for (ModuleLayout m : layout.modules()) {
            FdgModuleElement module = new FdgModuleElement();
            module.name = m.name();
            module.colour = m.colour();
            module.visible = m.visible() ? null : "no";
            for (Map.Entry<String, NodeLayout> e : m.nodes().entrySet()) {
                NodeLayout n = e.getValue();
                FdgNodeElement node = new FdgNodeElement();
                node.name = e.getKey();
                node.x = format(n.x());
                node.y = format(n.y());
                node.width = n.width() == null ? null : format(n.width());
                node.height = n.height() == null ? null : format(n.height());
                node.colour = n.colour();
                module.nodes.add(node);
            }
            root.modules.add(module);
        }
        try {
            XmlFragments.marshal(JaxbContexts.layout(), root, out);
        } catch (JAXBException e) {
            throw new IOException("cannot write the layout: " + e.getMessage(), e);
        }
    }

    /** Whole numbers without ".0", others as Java prints them: stable across load and save. */
    private static String format(double value) {
        return value == Math.rint(value) && Math.abs(value) < 1e15 ? Long.toString((long) value) : Double.toString(value);
    }
}
