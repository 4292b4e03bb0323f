package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlType;

/** {@code <pstructure>}: declares a Relation node ("process"). */
@XmlType(name = "pstructure", propOrder = {"name", "host", "path", "className", "params"})
public class PStructureElement extends StructureElement {
}
