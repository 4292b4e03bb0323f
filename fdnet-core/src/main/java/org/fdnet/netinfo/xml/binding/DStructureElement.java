package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlType;

/** {@code <dstructure>}: declares a Data node. */
@XmlType(name = "dstructure", propOrder = {"name", "host", "path", "className", "params"})
public class DStructureElement extends StructureElement {
}
