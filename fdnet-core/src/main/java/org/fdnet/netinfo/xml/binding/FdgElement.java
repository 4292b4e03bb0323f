package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlAttribute;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlRootElement;
import java.util.ArrayList;
import java.util.List;

/** {@code <fdg network="..">}: the root of a .fdg graphic side file (dtd/fdg.dtd). */
@XmlRootElement(name = "fdg")
@XmlAccessorType(XmlAccessType.FIELD)
public class FdgElement extends Located {
    @XmlAttribute
    public String network;
    @XmlElement(name = "module")
    public List<FdgModuleElement> modules = new ArrayList<>();
}
