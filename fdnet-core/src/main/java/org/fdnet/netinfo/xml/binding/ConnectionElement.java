package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlElements;
import java.util.ArrayList;
import java.util.List;

/** {@code connection (read|write)*}: a group of connections, in file order. */
@XmlAccessorType(XmlAccessType.FIELD)
public class ConnectionElement extends Located {
    @XmlElements({
        @XmlElement(name = "read", type = ReadElement.class),
        @XmlElement(name = "write", type = WriteElement.class)
    })
    public List<LinkElement> links = new ArrayList<>();
}
