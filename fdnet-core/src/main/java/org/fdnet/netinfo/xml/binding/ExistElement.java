package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlAttribute;

/** {@code <exist value="yes|no"/>}: whether the connection is made when the network starts. */
@XmlAccessorType(XmlAccessType.FIELD)
public class ExistElement {
    @XmlAttribute
    public String value;
}
