package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlElements;
import jakarta.xml.bind.annotation.XmlTransient;
import java.util.ArrayList;
import java.util.List;

/** {@code ((pstructure|dstructure)*,connection*)}: what {@code cnet} and {@code module} both hold. */
@XmlTransient
@XmlAccessorType(XmlAccessType.FIELD)
public abstract class ModuleBody extends Located {
    @XmlElements({
        @XmlElement(name = "pstructure", type = PStructureElement.class),
        @XmlElement(name = "dstructure", type = DStructureElement.class)
    })
    public List<StructureElement> structures = new ArrayList<>();
    @XmlElement(name = "connection")
    public List<ConnectionElement> connections = new ArrayList<>();
}
