package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlAttribute;
import jakarta.xml.bind.annotation.XmlType;

/** {@code <module name=".." loadatstart="yes|no">}: the 2004 Module extension. */
@XmlAccessorType(XmlAccessType.FIELD)
@XmlType(propOrder = {"structures", "connections"})
public class ModuleElement extends ModuleBody {
    @XmlAttribute(required = true)
    public String name;
    @XmlAttribute
    public String loadatstart;
}
