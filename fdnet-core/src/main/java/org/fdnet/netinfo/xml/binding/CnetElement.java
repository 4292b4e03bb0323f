package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlAttribute;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlRootElement;
import jakarta.xml.bind.annotation.XmlType;
import java.util.ArrayList;
import java.util.List;

/** {@code <cnet name="..">}: the root of a .fdn file. Its own nodes and connections form module main. */
@XmlRootElement(name = "cnet")
@XmlAccessorType(XmlAccessType.FIELD)
@XmlType(propOrder = {"structures", "connections", "modules"})
public class CnetElement extends ModuleBody {
    @XmlAttribute
    public String name;
    @XmlElement(name = "module")
    public List<ModuleElement> modules = new ArrayList<>();
}
