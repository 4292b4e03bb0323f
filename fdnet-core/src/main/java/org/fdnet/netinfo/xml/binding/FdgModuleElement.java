package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlAttribute;
import jakarta.xml.bind.annotation.XmlElement;
import java.util.ArrayList;
import java.util.List;

/** {@code <module name=".." colour="#RRGGBB" visible="yes|no">} of a .fdg file. */
@XmlAccessorType(XmlAccessType.FIELD)
public class FdgModuleElement extends Located {
    @XmlAttribute(required = true)
    public String name;
    @XmlAttribute
    public String colour;
    @XmlAttribute
    public String visible;
    @XmlElement(name = "node")
    public List<FdgNodeElement> nodes = new ArrayList<>();
}
